// `aspects query` and `aspects path` on RRRRR at ε = 0.3 (results/pose_query.*,
// apps/path_command.*, results/result_index.*): every command enclosure printed contains the
// root of f(x, ·) = 0 computed independently here by Newton in MPFR at 256 bits on the
// RRRRR equations written out by hand; a path's consecutive waypoints share a box; a path
// across CSNCs of different determinant signs is refused; the index round-trips exactly
// and rejects truncation and other versions. Membership of a pose in a box (pose.h) is
// decided exactly: checked against MPFR at 256 bits at box faces, at ±π and shifted by
// whole turns, so that no negative answer ("outside", "in no solution box") is false; a
// path across the ±π seam is printed unwrapped.
//
// The RRRRR result comes from the `query_fixture` test (aspects solve --out), or is solved
// here when that directory has no index.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "csnc_links.h"
#include "generalized_aspects.h"
#include "path_plan.h"
#include "results/loaded_result.h"
#include "results/pose.h"
#include "results/pose_query.h"
#include "results/result_index.h"
#include "results/same_command.h"
#include "results/sha256.h"
#include "test_util.h"

using namespace aspects;
using aspects_test::R;

namespace {

LoadedResult& rrrrr() {
  static LoadedResult* r = nullptr;
  if (r) return *r;
  const std::string dir = ASPECTS_QUERY_FIXTURE_DIR;
  try {
    r = new LoadedResult(load_result(dir));
  } catch (const IndexError&) {
    set_working_precision(53);
    Model m = parse_model(kDefaultModelText, "(embedded RRRRR)");
    AspectsConfig cfg;
    cfg.eps = 0.3;
    cfg.threads = 2;
    cfg.keep_link_proofs = false;
    AspectsResult res = compute_aspects(m, cfg);
    std::filesystem::create_directories(dir);
    write_result_index(dir + "/" + kResultIndexName,
                       build_result_index(m, res, 53, cfg.tau, cfg.eps, "(embedded RRRRR)"));
    r = new LoadedResult(load_result(dir));
  }
  return *r;
}

// RRRRR: f1 = (x1 − 8 cos q1)² + (x2 − 8 sin q1)² − 25 depends on q1 only, f2 =
// (x1 − 9 − 5 cos q2)² + (x2 − 5 sin q2)² − 64 on q2 only: two scalar Newton iterations
// at 256 bits from the double start. Returns false when it does not converge.
bool mpfr_root(const std::vector<double>& x, const std::vector<double>& start, std::vector<R>& q) {
  R x1(x[0]), x2(x[1]);
  q = {R(start[0]), R(start[1])};
  for (int it = 0; it < 60; ++it) {
    R s1 = sin(q[0]), c1 = cos(q[0]), s2 = sin(q[1]), c2 = cos(q[1]);
    R f1 = sqr(x1 - R(8) * c1) + sqr(x2 - R(8) * s1) - R(25);
    R d1 = R(16) * (x1 * s1 - x2 * c1);
    R f2 = sqr(x1 - R(9) - R(5) * c2) + sqr(x2 - R(5) * s2) - R(64);
    R d2 = R(10) * ((x1 - R(9)) * s2 - x2 * c2);
    R step1 = f1 / d1, step2 = f2 / d2;
    q[0] = q[0] - step1;
    q[1] = q[1] - step2;
    if (abs(step1) < R("1e-70") && abs(step2) < R("1e-70")) return true;
  }
  return false;
}

// A model and its result solved here, loaded as `aspects query` loads a result directory.
LoadedResult solve_text(const std::string& text, double eps, int prec) {
  set_working_precision(prec);
  Model m = parse_model(text, "(test)");
  AspectsConfig cfg;
  cfg.eps = eps;
  cfg.all_links = true;
  cfg.keep_link_proofs = false;
  AspectsResult res = compute_aspects(m, cfg);
  return load_result_from(build_result_index(m, res, prec, cfg.tau, cfg.eps, "(test)"), "(test)");
}

// A helix: q = 2x + 4πm solves it, so every pose has commands.
const char* kHelix =
    "robot HELIX\npose    x in [-pi, pi] periodic\ncommand q in [-10, 10]\n"
    "equation sin(q/2 - x) = 0\n";

// Reference: some k in [-3, 3] has lo <= p + 2πk <= hi, at 256 bits (asserted decisive:
// every comparison clears 2^-200).
bool reference_inside(double p, double lo, double hi, long& turns) {
  for (long k = -3; k <= 3; ++k) {
    R t = R(p) + R(2 * int(k)) * R::pi();
    R a = t - R(lo), b = R(hi) - t;
    EXPECT_TRUE(k == 0 || abs(a) > R("1e-60")) << p << " " << k;
    EXPECT_TRUE(k == 0 || abs(b) > R("1e-60")) << p << " " << k;
    if (a >= R(0) && b >= R(0)) {
      turns = k;
      return true;
    }
  }
  return false;
}

// The exact root lies in [lo, hi] (the double endpoints are exact reals).
bool encloses(double lo, double hi, const R& v) { return R(lo) <= v && v <= R(hi); }

std::vector<double> centre(const IndexSolutionBox& s) {
  return {0.5 * s.lo[0] + 0.5 * s.hi[0], 0.5 * s.lo[1] + 0.5 * s.hi[1]};
}

}  // namespace

TEST(QueryPath, QueryEnclosesTheMpfrRootInEveryBox) {
  LoadedResult& r = rrrrr();
  ModelEvaluator ev(r.model);
  // (10, -6) lies in the largest CSNC at this ε; (3, 5) in four working modes.
  for (std::vector<double> pose : {std::vector<double>{10, -6}, std::vector<double>{3, 5}}) {
    QueryResult q = query_pose(r, ev, pose);
    ASSERT_EQ(q.outcome, QueryOutcome::Answered);
    EXPECT_TRUE(q.unproved.empty());
    if (pose[0] == 10) {
      EXPECT_EQ(q.answers.front().csnc, 0);
    }
    std::vector<int32_t> csncs;
    for (const QueryAnswer& a : q.answers) {
      const IndexSolutionBox& s = r.index.solutions[a.solution];
      ASSERT_EQ(a.command.status, PointCommandStatus::Certified);
      EXPECT_LT(a.command.width(), 1e-12);
      std::vector<R> root;
      ASSERT_TRUE(mpfr_root(pose, {a.command.lo[0], a.command.lo[1]}, root));
      for (int j = 0; j < 2; ++j) {
        EXPECT_TRUE(encloses(a.command.lo[j], a.command.hi[j], root[j]))
            << "box " << a.box << " q" << j + 1 << " root " << root[j].str();
        EXPECT_TRUE(encloses(s.lo[2 + j], s.hi[2 + j], root[j]));  // κ_S(x) ∈ [q]
      }
      csncs.push_back(a.csnc);
    }
    EXPECT_TRUE(std::is_sorted(csncs.begin(), csncs.end()));
  }
}

// Issue 50, item 10: a pose on a face shared by solution boxes had its command listed once
// per box ("7 certified command(s)" where 4 were distinct). Poses on the upper x1 face of
// solution boxes: the answers are the distinct MPFR roots, each once; every box merged into
// an answer holds the pose and, by its own certified command, the same root. Before the
// merge, 125 of these poses had a root listed twice or more.
TEST(QueryPath, EachSolutionOfAPoseOnSharedFacesIsListedOnce) {
  LoadedResult& r = rrrrr();
  ModelEvaluator ev(r.model);
  HsWorkspace ws;
  int poses = 0, merged = 0;
  for (size_t i = 0; i < r.index.solutions.size(); i += 53) {
    const IndexSolutionBox& s = r.index.solutions[i];
    const std::vector<double> pose = {s.hi[0], 0.5 * s.lo[1] + 0.5 * s.hi[1]};
    QueryResult q = query_pose(r, ev, pose);
    if (q.outcome != QueryOutcome::Answered) continue;
    ++poses;
    EXPECT_TRUE(q.not_proved_distinct.empty()) << "pose " << pose[0] << "," << pose[1];
    std::vector<std::vector<R>> roots;  // one per answer
    for (const QueryAnswer& a : q.answers) {
      std::vector<R> root;
      ASSERT_TRUE(mpfr_root(pose, {a.command.lo[0], a.command.lo[1]}, root));
      for (int j = 0; j < 2; ++j) EXPECT_TRUE(encloses(a.command.lo[j], a.command.hi[j], root[j]));
      // Each box merged here certifies, on its own, a command enclosing the same root.
      ASSERT_EQ(a.same_boxes.size(), a.same_csncs.size());
      merged += !a.same_boxes.empty();
      for (uint32_t id : a.same_boxes) {
        const auto at = std::find_if(r.index.solutions.begin(), r.index.solutions.end(),
                                     [&](const IndexSolutionBox& b) { return b.id == id; });
        ASSERT_NE(at, r.index.solutions.end());
        EXPECT_EQ(pose_in_box(r.model, pose, at->lo.data(), at->hi.data()), Membership::Inside);
        PointCommand own = certified_command(ev, at->lo.data(), at->hi.data(), pose, r.index.tau, ws);
        ASSERT_EQ(own.status, PointCommandStatus::Certified);
        std::vector<R> own_root;
        ASSERT_TRUE(mpfr_root(pose, {own.lo[0], own.lo[1]}, own_root));
        for (int j = 0; j < 2; ++j)  // the same angle (the commands are periodic)
          EXPECT_LT(abs(sin((own_root[j] - root[j]) / R(2))).d(), 1e-60) << "box " << id;
      }
      // No two answers are one root.
      for (const std::vector<R>& other : roots)
        EXPECT_GT(std::max(abs(sin((other[0] - root[0]) / R(2))).d(),
                           abs(sin((other[1] - root[1]) / R(2))).d()), 1e-9)
            << "pose " << pose[0] << "," << pose[1] << ": a root listed twice";
      roots.push_back(root);
    }
  }
  EXPECT_GT(poses, 20);
  EXPECT_GT(merged, 0) << "no pose on a shared face: the test shows nothing";
}

// same_command (results/same_command.h) on one pose of RRRRR: a command and itself shifted by a
// whole turn are one (q1, q2 periodic); two different roots are distinct; an enclosure
// holding two roots proves neither.
TEST(QueryPath, SameCommandProvesOneTwoOrNeither) {
  LoadedResult& r = rrrrr();
  ModelEvaluator ev(r.model);
  HsWorkspace ws;
  const std::vector<double> pose = {3, 5};
  QueryResult q = query_pose(r, ev, pose);
  ASSERT_EQ(q.outcome, QueryOutcome::Answered);
  ASSERT_GE(q.answers.size(), 2u);
  const PointCommand& a = q.answers[0].command;
  const PointCommand& b = q.answers[1].command;
  const double tau = r.index.tau;
  EXPECT_EQ(same_command(ev, pose, a, a, tau, ws), SameCommand::Same);
  EXPECT_EQ(same_command(ev, pose, a, b, tau, ws), SameCommand::Distinct);
  PointCommand turned = a;  // a - 2π, rounded outward
  for (int j = 0; j < 2; ++j) {
    turned.lo[j] = (R(a.lo[j]) - R(2) * R::pi()).d() - 1e-14;
    turned.hi[j] = (R(a.hi[j]) - R(2) * R::pi()).d() + 1e-14;
  }
  EXPECT_EQ(same_command(ev, pose, a, turned, tau, ws), SameCommand::Same);
  PointCommand both = a;  // the hull of both roots: two solutions in it, no uniqueness
  for (int j = 0; j < 2; ++j) {
    both.lo[j] = std::min(a.lo[j], b.lo[j]);
    both.hi[j] = std::max(a.hi[j], b.hi[j]);
  }
  EXPECT_EQ(same_command(ev, pose, a, both, tau, ws), SameCommand::Unknown);
}

TEST(PoseMembership, FacesAndWholeTurnsAreDecidedAsMpfrDecides) {
  // Poses on and within a few ulps of a face b, shifted by ±2π and ±4π (rounded to
  // doubles), against the two boxes [b - 0.3, b] and [b, b + 0.3]; the faces include ±π
  // (the seam of the root cell) and the double nearest -π/2 (a bisection point). The
  // conservative test (the 53-bit enclosure of p + 2πk inside the box) put 5 of these
  // poses in neither box.
  const double faces[] = {-M_PI, M_PI, -1.5707963267948966, 0.5, std::nextafter(M_PI, 4.0)};
  int inside = 0, decided = 0;
  for (double b : faces)
    for (long k : {-2L, -1L, 1L, 2L})
      for (int ulps = -3; ulps <= 3; ++ulps) {
        double p = (R(b) - R(2 * int(k)) * R::pi()).d();
        for (int u = 0; u < std::abs(ulps); ++u) p = std::nextafter(p, ulps > 0 ? 10.0 : -10.0);
        bool in_some = false;
        for (auto [lo, hi] : {std::pair{b - 0.3, b}, std::pair{b, b + 0.3}}) {
          long turns = 99, want = 0;
          Membership m = coordinate_membership(p, lo, hi, true, turns);
          bool in = reference_inside(p, lo, hi, want);
          ASSERT_NE(m, Membership::Undecided) << p;
          EXPECT_EQ(m == Membership::Inside, in) << "p " << p << " box " << lo << " " << hi;
          if (in) {
            EXPECT_EQ(turns, want);
          }
          in_some = in_some || m == Membership::Inside;
          inside += m == Membership::Inside;
          ++decided;
        }
        EXPECT_TRUE(in_some) << p << ": the two boxes meet at b, one holds p modulo 2π";
      }
  EXPECT_EQ(decided, 5 * 4 * 7 * 2);
  EXPECT_GE(inside, 5 * 4 * 7);
}

TEST(PoseMembership, UnshiftedFacesAreExactAndPiIsOnBothSidesOfTheSeam) {
  const double lo = -0.25, hi = 0.75;
  long t = 7;
  EXPECT_EQ(coordinate_membership(lo, lo, hi, false, t), Membership::Inside);
  EXPECT_EQ(t, 0);
  EXPECT_EQ(coordinate_membership(hi, lo, hi, false, t), Membership::Inside);
  EXPECT_EQ(coordinate_membership(std::nextafter(lo, -1.0), lo, hi, false, t), Membership::Outside);
  EXPECT_EQ(coordinate_membership(std::nextafter(hi, 1.0), lo, hi, true, t), Membership::Outside);
  // The root cell of [-pi, pi] rounded outward holds both M_PI (< π) and M_PI - 2π
  // (> -π - 2^-51), and -M_PI and -M_PI + 2π.
  const double root_lo = std::nextafter(-M_PI, -4.0), root_hi = std::nextafter(M_PI, 4.0);
  EXPECT_EQ(coordinate_membership(M_PI, root_lo, -3.0, true, t), Membership::Inside);
  EXPECT_EQ(t, -1);
  EXPECT_EQ(coordinate_membership(-M_PI, 3.0, root_hi, true, t), Membership::Inside);
  EXPECT_EQ(t, 1);
  // -π - 2^-50 is outside; its shift by 2π is π - 2^-50 + ..., inside [3, root_hi].
  EXPECT_EQ(coordinate_membership(-M_PI - 0x1p-50, root_lo, -3.0, true, t), Membership::Outside);
  EXPECT_EQ(coordinate_membership(-M_PI - 0x1p-50, 3.0, root_hi, true, t), Membership::Inside);
}

TEST(PoseMembership, UndecidedWhenThePrecisionRunsOutNeverOutside) {
  // p + 2π within 2^-50 of the face 0.5: below 128 bits of π no MPFR step runs, and only
  // the double test (which cannot decide so close) is left.
  const double p = (R(0.5) - R(2) * R::pi()).d();
  long t = 0;
  EXPECT_EQ(coordinate_membership(p, 0.5, 0.8, true, t, 64), Membership::Undecided);
  EXPECT_EQ(coordinate_membership(p, 0.2, 0.5, true, t, 64), Membership::Undecided);
  EXPECT_EQ(shifted_sign(p, 1, 0.5, 64), 0);
  const int exact = shifted_sign(p, 1, 0.5);
  EXPECT_EQ(exact, (R(p) + R(2) * R::pi() > R(0.5)) ? 1 : -1);
  EXPECT_EQ(coordinate_membership(p, 0.5, 0.8, true, t) == Membership::Inside, exact > 0);
  EXPECT_EQ(coordinate_membership(p, 0.2, 0.5, true, t) == Membership::Inside, exact < 0);
}

TEST(QueryPath, HelixPoseShiftedOntoAFaceHasItsCommands) {
  // 4.71238898038469 - 2π lies on a face of the subdivision: the same pose as
  // -1.5707963267948966, 4 certified commands. A test sure only of "inside" calls it outside
  // the workspace (at 24 bits, in a window about 5e-7 wide).
  for (int prec : {53, 24}) {
    LoadedResult r = solve_text(kHelix, 0.3, prec);
    ModelEvaluator ev(r.model);
    QueryResult shifted = query_pose(r, ev, {4.71238898038469});
    QueryResult plain = query_pose(r, ev, {-1.5707963267948966});
    EXPECT_EQ(plain.outcome, QueryOutcome::Answered) << prec;
    EXPECT_EQ(shifted.outcome, plain.outcome) << prec;
    EXPECT_EQ(shifted.answers.size(), plain.answers.size()) << prec;
    if (prec == 53) {
      EXPECT_EQ(plain.answers.size(), 4u);
    }
    EXPECT_TRUE(shifted.unknown.empty());
    PathResult p = plan_path(r, ev, {4.71238898038469}, {0.5}, -1);
    EXPECT_EQ(p.outcome, PathOutcome::Found) << prec << " " << p.failure;
    // At ±π, near -π/2 and elsewhere, shifted by whole turns (then rounded): the solution
    // boxes found are those that hold the pose at 256 bits.
    for (double x : {M_PI, -M_PI, -1.5707963267948966, 2.5, -0.75})
      for (double s : {0.0, 2 * M_PI, -2 * M_PI, 4 * M_PI}) {
        std::vector<size_t> want;
        for (size_t i = 0; i < r.index.solutions.size(); ++i) {
          long turns = 0;
          const IndexSolutionBox& b = r.index.solutions[i];
          if (reference_inside(x + s, b.lo[0], b.hi[0], turns)) want.push_back(i);
        }
        EXPECT_EQ(solution_boxes_at(r, {x + s}).inside, want) << x << " + " << s;
        EXPECT_GE(want.size(), 3u) << x << " + " << s;
        QueryResult q = query_pose(r, ev, {x + s});
        EXPECT_EQ(q.outcome, QueryOutcome::Answered);
      }
  }
  set_working_precision(53);
}

TEST(QueryPath, PathAcrossTheSeamIsPrintedUnwrapped) {
  // tests/models/seam_pose.robot: from 2.9 to -2.9 the short way crosses ±π. Printed
  // unwrapped, the goal is -2.9 + 2π and the path is monotone: its length is the distance
  // between its printed ends, and each segment's printed ends lie in its box after one
  // common whole-turn shift.
  LoadedResult r = solve_text(
      "robot Seam\npose    t in [-pi, pi] periodic\ncommand q in [0, 4]\n"
      "equation q - 2 - cos(t) + sin(t)/2 = 0\n", 0.1, 53);
  ModelEvaluator ev(r.model);
  PathResult p = plan_path(r, ev, {2.9}, {-2.9}, -1, PathShape::Chain);
  ASSERT_EQ(p.outcome, PathOutcome::Found) << p.failure;
  ASSERT_EQ(p.waypoints.size(), 3u);
  EXPECT_EQ(p.waypoints.front().turns, std::vector<long>{0});
  EXPECT_EQ(p.waypoints.back().turns, std::vector<long>{1});
  EXPECT_NEAR(p.length, 2 * M_PI - 5.8, 1e-12);
  double previous = -10;
  for (size_t i = 0; i < p.waypoints.size(); ++i) {
    const Waypoint& w = p.waypoints[i];
    const R printed = R(w.pose[0]) + R(2 * int(w.turns[0])) * R::pi();
    EXPECT_GT(printed.d(), previous) << "waypoint " << i;
    previous = printed.d();
    if (i + 1 == p.waypoints.size()) break;
    const IndexSolutionBox& s = r.index.solutions[w.solution];
    const long shift = w.turns[0] - w.box_turns[0];
    const R next = R(p.waypoints[i + 1].pose[0]) +
                   R(2 * int(p.waypoints[i + 1].turns[0] - shift)) * R::pi();
    const R here = printed - R(2 * int(shift)) * R::pi();
    EXPECT_TRUE(R(s.lo[0]) <= here && here <= R(s.hi[0])) << "segment " << i;
    EXPECT_TRUE(R(s.lo[0]) <= next && next <= R(s.hi[0])) << "segment " << i;
  }
}

TEST(QueryPath, QueryOutsideTheWorkspaceSaysSo) {
  LoadedResult& r = rrrrr();
  ModelEvaluator ev(r.model);
  QueryResult q = query_pose(r, ev, {19.5, 19.5});  // farther than 13 from both bases
  EXPECT_EQ(q.outcome, QueryOutcome::OutsideWorkspace);
  EXPECT_TRUE(q.answers.empty());
  EXPECT_TRUE(q.undecided.empty());
}

TEST(QueryPath, NegativeAnswersOnlyWhereNoBoxHoldsThePose) {
  LoadedResult& r = rrrrr();
  ModelEvaluator ev(r.model);
  // Farther than 13 from both bases: no box, so no path from or to it.
  EXPECT_EQ(plan_path(r, ev, {19.5, 19.5}, {10, -6}, -1).outcome, PathOutcome::StartNowhere);
  EXPECT_EQ(plan_path(r, ev, {10, -6}, {19.5, 19.5}, -1).outcome, PathOutcome::GoalNowhere);
  // Every corner of a solution box (on two faces) lies in that box, and one ulp outside
  // the lower corner it does not (boxes are closed, the test exact).
  int corners = 0;
  for (size_t i = 0; i < r.index.solutions.size(); i += 97) {
    const IndexSolutionBox& s = r.index.solutions[i];
    for (const std::vector<double>& c : {std::vector<double>{s.lo[0], s.lo[1]},
                                         std::vector<double>{s.hi[0], s.hi[1]}}) {
      std::vector<size_t> at = solution_boxes_at(r, c).inside;
      EXPECT_TRUE(std::count(at.begin(), at.end(), i)) << "box " << s.id;
      EXPECT_NE(query_pose(r, ev, c).outcome, QueryOutcome::OutsideWorkspace);
      ++corners;
    }
    std::vector<double> out = {std::nextafter(s.lo[0], -100.0), s.lo[1]};
    EXPECT_EQ(pose_in_box(r.model, out, s.lo.data(), s.hi.data()), Membership::Outside);
  }
  EXPECT_GT(corners, 100);
}

TEST(QueryPath, PathAcrossTheLargestCsncIsCertifiedSegmentBySegment) {
  LoadedResult& r = rrrrr();
  ModelEvaluator ev(r.model);
  // The two boxes of CSNC 0 farthest apart in x1: their pose centres.
  const IndexSolutionBox *left = nullptr, *right = nullptr;
  for (const IndexSolutionBox& s : r.index.solutions) {
    if (s.csnc != 0) continue;
    if (!left || s.lo[0] < left->lo[0]) left = &s;
    if (!right || s.hi[0] > right->hi[0]) right = &s;
  }
  ASSERT_TRUE(left && right);
  std::vector<double> from = centre(*left), to = centre(*right);
  PathResult p = plan_path(r, ev, from, to, 0, PathShape::Chain);
  ASSERT_EQ(p.outcome, PathOutcome::Found) << p.failure;
  EXPECT_EQ(p.csnc, 0);
  ASSERT_GE(p.waypoints.size(), 4u);
  EXPECT_EQ(p.waypoints.front().pose, from);
  EXPECT_EQ(p.waypoints.back().pose, to);
  EXPECT_EQ(p.waypoints.front().kind, WaypointKind::Start);
  EXPECT_EQ(p.waypoints.back().kind, WaypointKind::Goal);
  auto in_pose = [](const IndexSolutionBox& s, const std::vector<double>& x) {
    return s.lo[0] <= x[0] && x[0] <= s.hi[0] && s.lo[1] <= x[1] && x[1] <= s.hi[1];
  };
  for (size_t i = 0; i < p.waypoints.size(); ++i) {
    const Waypoint& w = p.waypoints[i];
    const IndexSolutionBox& s = r.index.solutions[w.solution];
    EXPECT_EQ(s.id, w.box);
    EXPECT_EQ(s.csnc, 0);
    ASSERT_EQ(w.command.status, PointCommandStatus::Certified) << "waypoint " << i;
    EXPECT_TRUE(in_pose(s, w.pose)) << "waypoint " << i;
    if (i + 1 < p.waypoints.size()) {
      EXPECT_TRUE(in_pose(s, p.waypoints[i + 1].pose)) << "segment " << i << " leaves box " << s.id;
    }
    std::vector<R> root;
    ASSERT_TRUE(mpfr_root(w.pose, {w.command.lo[0], w.command.lo[1]}, root));
    for (int j = 0; j < 2; ++j) {
      EXPECT_TRUE(encloses(w.command.lo[j], w.command.hi[j], root[j])) << "waypoint " << i;
      EXPECT_TRUE(encloses(s.lo[2 + j], s.hi[2 + j], root[j])) << "waypoint " << i;
    }
    if (w.kind == WaypointKind::Witness) {
      // The previous box's κ agrees at the witness: the same root lies in its [q]
      // (modulo 2π: a link may cross the ±π seam of a command).
      const IndexSolutionBox& prev = r.index.solutions[p.waypoints[i - 1].solution];
      for (int j = 0; j < 2; ++j) {
        bool in = false;
        for (int k = -1; k <= 1; ++k)
          in = in || encloses(prev.lo[2 + j], prev.hi[2 + j], root[j] + R(2 * k) * R::pi());
        EXPECT_TRUE(in) << "witness " << i << " q" << j + 1;
      }
    }
  }
}

// Every segment of a path is certified, re-checked here through the library.
void expect_certified(const LoadedResult& r, ModelEvaluator& ev, const PathResult& p) {
  CsncLinks links(r, ev, p.csnc);
  size_t bad = 0;
  SegmentCheck why = SegmentCheck::Certified;
  EXPECT_EQ(check_path(r, links, p, &bad, &why), PathCheck::Certified)
      << "segment " << bad << ": " << segment_check_name(why);
  ASSERT_EQ(p.segments.size() + 1, p.waypoints.size());
  for (size_t i = 0; i < p.segments.size(); ++i) {
    const Waypoint& a = p.waypoints[i];
    const Waypoint& b = p.waypoints[i + 1];
    EXPECT_EQ(check_segment(r, links, {a.pose, a.turns}, {b.pose, b.turns}, p.segments[i]),
              SegmentCheck::Certified) << "segment " << i;
  }
}

TEST(PathShortcut, ReadmeExampleIsOneStraightSegment) {
  // README: from (10, -6) to (4, -9) on the default RRRRR (here the fixture, eps 0.3,
  // without --all-links). The chain of links proved on demand has 11 waypoints; the
  // shortcut keeps 2: the straight segment, through a chain of linked boxes.
  LoadedResult& r = rrrrr();
  ModelEvaluator ev(r.model);
  PathResult chain = plan_path(r, ev, {10, -6}, {4, -9}, -1, PathShape::Chain);
  ASSERT_EQ(chain.outcome, PathOutcome::Found) << chain.failure;
  EXPECT_EQ(chain.waypoints.size(), 11u);
  expect_certified(r, ev, chain);
  PathResult p = plan_path(r, ev, {10, -6}, {4, -9}, -1);
  ASSERT_EQ(p.outcome, PathOutcome::Found) << p.failure;
  EXPECT_EQ(p.csnc, 0);
  EXPECT_EQ(p.waypoints.size(), 2u);
  EXPECT_EQ(p.chain_waypoints, 11u);
  EXPECT_DOUBLE_EQ(p.straight, std::hypot(6.0, 3.0));
  EXPECT_LT(p.length / p.straight, 1 + 1e-12);
  EXPECT_GT(p.segments.front().boxes.size(), 5u);  // a chain of boxes, not one box
  expect_certified(r, ev, p);
}

TEST(PathShortcut, AroundAHoleTheShortcutKeepsFewCornersAllCertified) {
  // From (3.6, -2.6) to (3.6, 3.7) in CSNC 1 the straight line leaves the CSNC: the chain of
  // links proved on demand has 30 waypoints, the shortcut 5 (3 corners), length 6.6614 for
  // 6.3 straight.
  LoadedResult& r = rrrrr();
  ModelEvaluator ev(r.model);
  const std::vector<double> from{3.6, -2.6}, to{3.6, 3.7};
  PathResult chain = plan_path(r, ev, from, to, -1, PathShape::Chain);
  PathResult p = plan_path(r, ev, from, to, -1);
  ASSERT_EQ(p.outcome, PathOutcome::Found) << p.failure;
  EXPECT_EQ(p.csnc, 1);
  EXPECT_EQ(chain.waypoints.size(), 30u);
  expect_certified(r, ev, chain);
  EXPECT_EQ(p.waypoints.size(), 5u);
  EXPECT_EQ(p.waypoints[2].kind, WaypointKind::Corner);
  EXPECT_NEAR(p.length, 6.66141677321745, 1e-9);
  EXPECT_LT(p.length / p.straight, 1.058);
  EXPECT_GT(chain.length / chain.straight, 1.1);
  EXPECT_LT(p.length, chain.length);
  expect_certified(r, ev, p);
  // The check is no formality: a segment moved off its boxes, or boxes not linked, fail.
  PathResult moved = p;
  moved.waypoints[1].pose[1] += 3;
  CsncLinks links(r, ev, p.csnc);
  EXPECT_NE(check_path(r, links, moved), PathCheck::Certified);
  PathResult other = p;
  const std::vector<size_t> far = solution_boxes_at(r, to).inside;
  other.segments.front().boxes.back().solution = far.front();
  EXPECT_NE(check_path(r, links, other), PathCheck::Certified);
  // Whole turns on x1, which is not periodic: the shifted boxes are no solution boxes.
  Segment turned = p.segments.front();
  for (PlacedBox& b : turned.boxes) b.shift[0] = 1;
  for (Crossing& c : turned.crossings)
    if (c.coordinate == 0) c.turns = 1;
  const Waypoint& a = p.waypoints[0];
  const Waypoint& b = p.waypoints[1];
  EXPECT_EQ(check_segment(r, links, {a.pose, {1, 0}}, {b.pose, {1, 0}}, turned),
            SegmentCheck::Malformed);
}

TEST(QueryPath, PathAcrossCsncsOfDifferentSignsIsRefused) {
  LoadedResult& r = rrrrr();
  ModelEvaluator ev(r.model);
  const IndexSolutionBox* start = nullptr;
  for (const IndexSolutionBox& s : r.index.solutions)
    if (s.csnc == 0) start = &s;
  ASSERT_TRUE(start);
  // A goal whose every CSNC differs from CSNC 0 in the sign of some factor.
  auto differs = [&](const IndexSolutionBox& s) {
    for (size_t f = 0; f < s.signs.size(); ++f)
      if (s.signs[f] != 0 && start->signs[f] != 0 && s.signs[f] != start->signs[f]) return true;
    return false;
  };
  std::vector<double> goal;
  for (const IndexSolutionBox& s : r.index.solutions) {
    if (s.csnc == 0 || uint32_t(s.csnc) >= r.index.filtered || !differs(s)) continue;
    std::vector<size_t> at = solution_boxes_at(r, centre(s)).inside;
    bool all_differ = std::all_of(at.begin(), at.end(), [&](size_t i) {
      return differs(r.index.solutions[i]);
    });
    if (all_differ) {
      goal = centre(s);
      break;
    }
  }
  ASSERT_FALSE(goal.empty());
  PathResult p = plan_path(r, ev, centre(*start), goal, 0);
  EXPECT_EQ(p.outcome, PathOutcome::DifferentSigns);
  EXPECT_TRUE(p.waypoints.empty());
  EXPECT_FALSE(std::count(p.goal_csncs.begin(), p.goal_csncs.end(), 0));
}

TEST(ResultIndex, RoundTripsExactlyAndRejectsDamage) {
  LoadedResult& r = rrrrr();
  const std::string bytes = encode_result_index(r.index);
  EXPECT_EQ(encode_result_index(decode_result_index(bytes, "t")), bytes);
  EXPECT_GT(r.index.links.size(), 1000u);
  auto message = [](const std::string& b) {
    try {
      decode_result_index(b, "t");
    } catch (const IndexError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(bytes.substr(0, bytes.size() / 2)).find("truncated"), std::string::npos);
  EXPECT_NE(message(bytes + "x").find("missing end marker or checksum"), std::string::npos);
  std::string other = bytes;
  other[14] = 3;  // the version follows the 14-byte magic
  EXPECT_NE(message(other).find("result index version 3, this aspects reads version 2"),
            std::string::npos);
  std::string magic = bytes;
  magic[0] = 'A';
  EXPECT_NE(message(magic).find("bad magic"), std::string::npos);
  // Readers merge the two box lists by id, so each must be in increasing id order.
  ResultIndex swapped = r.index;
  ASSERT_GT(swapped.undecided.size(), 1u);
  std::swap(swapped.undecided[0], swapped.undecided[1]);
  EXPECT_NE(message(encode_result_index(swapped)).find("undecided box ids not increasing"),
            std::string::npos);
}

TEST(ResultIndex, RecomputedWitnessesAreTheRecordedOnes) {
  // Without link proofs (--no-cert) the index recomputes each witness with certify_link's
  // rule; it must be the very double the proof used.
  set_working_precision(53);
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rrrrr.robot");
  AspectsConfig cfg;
  cfg.eps = 1.5;
  AspectsResult with = compute_aspects(m, cfg);
  ASSERT_EQ(with.link_proofs.size(), with.certified_links.size());
  ASSERT_GT(with.certified_links.size(), 10u);
  AspectsResult without = with;
  without.link_proofs = LinkRecords(m.n());
  ResultIndex a = build_result_index(m, with, 53, cfg.tau, cfg.eps, "x");
  ResultIndex b = build_result_index(m, without, 53, cfg.tau, cfg.eps, "x");
  ASSERT_EQ(a.links.size(), b.links.size());
  for (size_t i = 0; i < a.links.size(); ++i) EXPECT_EQ(a.links[i].witness, b.links[i].witness);
}

TEST(ResultIndex, StreamedIndexIsTheCollectedOneByteForByte) {
  // `aspects solve` writes the index record by record; query and the tests build it whole.
  // Both with and without link proofs (the witnesses kept or recomputed).
  set_working_precision(53);
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rrrrr.robot");
  AspectsConfig cfg;
  cfg.eps = 1;
  AspectsResult with = compute_aspects(m, cfg);
  AspectsResult without = with;
  without.link_proofs = LinkRecords(m.n());
  const std::string dir = ::testing::TempDir() + "streamed_index";
  std::filesystem::create_directories(dir);
  for (const AspectsResult* r : {&with, &without}) {
    const std::string path = dir + "/" + kResultIndexName;
    const CertificateId cert{"aspects.cert.zst", std::string(64, 'a')};
    const std::string sha =
        write_result_index(path, m, *r, 53, cfg.tau, cfg.eps, "x", [&] { return cert; });
    std::ifstream in(path, std::ios::binary);
    const std::string streamed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ResultIndex idx = build_result_index(m, *r, 53, cfg.tau, cfg.eps, "x");
    idx.certificate_file = cert.file;
    idx.certificate_sha256 = cert.sha256;
    // The returned hash is the whole file's, which reading it finds again.
    EXPECT_EQ(sha, sha256_hex_of(streamed));
    const ResultIndex back = decode_result_index(streamed, "t");
    EXPECT_EQ(back.sha256, sha);
    EXPECT_EQ(back.certificate_file, cert.file);
    EXPECT_EQ(back.certificate_sha256, cert.sha256);
    ASSERT_GT(idx.solutions.size(), 100u);
    ASSERT_GT(idx.undecided.size(), 100u);
    ASSERT_GT(idx.links.size(), 10u);
    EXPECT_EQ(streamed, encode_result_index(idx));
  }
}

TEST(ResultIndex, EveryTruncationAndByteFlipIsRejectedOrReadNeverACrash) {
  // A small index (the seam model of tests/models), damaged at every length and at random
  // bytes: decode either throws IndexError or returns; under the sanitizers it must not
  // read out of bounds or allocate from a damaged count.
  set_working_precision(53);
  Model m = load_model(std::string(ASPECTS_TEST_MODELS_DIR) + "/seam_pose.robot");
  AspectsConfig cfg;
  cfg.eps = 0.1;
  AspectsResult res = compute_aspects(m, cfg);
  const std::string bytes =
      encode_result_index(build_result_index(m, res, 53, cfg.tau, cfg.eps, "seam"));
  int rejected = 0;
  for (size_t len = 0; len < bytes.size(); ++len) {
    try {
      decode_result_index(bytes.substr(0, len), "t");
    } catch (const IndexError&) {
      ++rejected;
    }
  }
  EXPECT_EQ(rejected, int(bytes.size()));  // no proper prefix is a valid index
  // Every change of a byte is refused: the checksum that ends the index covers the rest
  // (issue 50: a sign flipped in aspects.idx was printed by query as certified).
  std::mt19937 g(11);
  int changed = 0;
  rejected = 0;
  for (int k = 0; k < 3000; ++k) {
    std::string d = bytes;
    size_t at = std::uniform_int_distribution<size_t>(0, d.size() - 1)(g);
    d[at] = char(std::uniform_int_distribution<int>(0, 255)(g));
    changed += d != bytes;
    try {
      decode_result_index(d, "t");
    } catch (const IndexError&) {
      ++rejected;
    }
  }
  EXPECT_EQ(rejected, changed);
  EXPECT_GT(changed, 2900);
}

TEST(ResultIndex, AFlippedSignIsRefusedByItsChecksum) {
  // The first solution box's first sign, flipped as the review did: the index is refused
  // with a message saying why, not read with the other sign.
  LoadedResult& r = rrrrr();
  ResultIndex flipped = r.index;
  const std::string bytes = encode_result_index(r.index);
  flipped.solutions[0].signs[0] = int8_t(-flipped.solutions[0].signs[0]);
  std::string edited = encode_result_index(flipped);
  ASSERT_EQ(edited.size(), bytes.size());
  edited.replace(edited.size() - 32, 32, bytes.substr(bytes.size() - 32));  // the old checksum
  try {
    decode_result_index(edited, "t");
    ADD_FAILURE() << "accepted";
  } catch (const IndexError& e) {
    EXPECT_EQ(std::string(e.what()),
              "t: the result index does not match its checksum: damaged or edited since "
              "`aspects solve` wrote it (re-run `aspects solve --out`)");
  }
}
