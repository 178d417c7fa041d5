// Additional constraints (paper 5.4): parsing of formulas, three-valued truth on boxes,
// soundness of atom enclosures at random points, the inner test of solution boxes
// against independent geometric predicates, and the CSNC counts of the constrained
// RRRRR models.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/constraints.h"
#include "generalized_aspects.h"

using namespace aspects;

namespace {

const std::string kHead = "robot T\npose x in [-4, 4]\ncommand q in [-4, 4]\nequation x - q = 0\n";

Truth truth_on(const std::string& constraint, double xlo, double xhi, double qlo = -4,
               double qhi = 4) {
  set_working_precision(53);
  Model m = parse_model(kHead + "constraint " + constraint + "\n", "t.robot");
  ModelEvaluator ev(m);
  ConstraintChecker cc(m, ev);
  Box b = {Interval(xlo, xhi), Interval(qlo, qhi)};
  return cc.evaluate(b);
}

std::string robot_path(const std::string& f) { return std::string(ASPECTS_ROBOTS_DIR) + "/" + f; }

}  // namespace

TEST(ConstraintParsing, FormulaStructure) {
  set_working_precision(53);
  Model m = parse_model(kHead + "constraint x >= q and (x < 1 or (q + 1) > 0)\n", "t.robot");
  ASSERT_EQ(m.constraints.size(), 1u);
  const FormulaNode& root = m.formula[m.constraints[0].root];
  ASSERT_EQ(root.kind, FormulaNode::And);
  ASSERT_EQ(root.kids.size(), 2u);
  EXPECT_EQ(m.formula[root.kids[0]].kind, FormulaNode::Atom);
  EXPECT_FALSE(m.formula[root.kids[0]].strict);
  const FormulaNode& disj = m.formula[root.kids[1]];
  ASSERT_EQ(disj.kind, FormulaNode::Or);
  EXPECT_TRUE(m.formula[disj.kids[0]].strict);
  EXPECT_TRUE(m.formula[disj.kids[1]].strict);  // "(q + 1) > 0": an expression in parentheses
  EXPECT_EQ(m.constraint_atoms.size(), 3u);
}

TEST(ConstraintTruth, AtomsOnBoxes) {
  EXPECT_EQ(truth_on("x >= 0", 1, 2), Truth::True);
  EXPECT_EQ(truth_on("x >= 3", 1, 2), Truth::False);
  EXPECT_EQ(truth_on("x >= 1.5", 1, 2), Truth::Unknown);
  EXPECT_EQ(truth_on("x >= 1", 1, 2), Truth::True);    // non-strict at the boundary
  EXPECT_EQ(truth_on("x > 1", 1, 2), Truth::Unknown);   // strict fails at x = 1
  EXPECT_EQ(truth_on("x > 2", 1, 2), Truth::False);     // holds at no point
  EXPECT_EQ(truth_on("x <= 2", 1, 2), Truth::True);
  EXPECT_EQ(truth_on("x < 1", 1, 2), Truth::False);
  // 0.1 is not a double. The double nearest to it is above it, so x >= 0.1 holds there
  // (provably: 0.1 is enclosed with its upper end on that double), while x <= 0.1 is
  // false there but not provably so: the enclosure of 0.1 - x is [-2^-57ish, 0].
  EXPECT_EQ(truth_on("x >= 0.1", 0.1, 0.1), Truth::True);
  EXPECT_EQ(truth_on("x <= 0.1", 0.1, 0.1), Truth::Unknown);
}

TEST(ConstraintTruth, KleeneConnectives) {
  EXPECT_EQ(truth_on("x >= 0 and x <= 3", 1, 2), Truth::True);
  EXPECT_EQ(truth_on("x >= 0 and x >= 3", 1, 2), Truth::False);
  EXPECT_EQ(truth_on("x >= 1.5 and x >= 0", 1, 2), Truth::Unknown);
  EXPECT_EQ(truth_on("x >= 1.5 or x >= 0", 1, 2), Truth::True);
  EXPECT_EQ(truth_on("x >= 3 or x < 0", 1, 2), Truth::False);
  EXPECT_EQ(truth_on("x >= 3 or x >= 1.5", 1, 2), Truth::Unknown);
}

TEST(ConstraintTruth, UndefinedPointsAreInfeasible) {
  EXPECT_EQ(truth_on("sqrt(x) >= 0", -1, 1), Truth::Unknown);  // undefined for x < 0
  EXPECT_EQ(truth_on("sqrt(x) >= 0", -2, -1), Truth::False);
  EXPECT_EQ(truth_on("sqrt(x) >= 0", 1, 2), Truth::True);
}

TEST(ConstraintTruth, ZeroTimesUndefinedIsStillUndefined) {
  // 0*sqrt(-x) must not be simplified away: it is undefined for x > 0.
  EXPECT_EQ(truth_on("x + 0*sqrt(-x) >= 0", 1, 2), Truth::False);
  EXPECT_EQ(truth_on("x + 0/sqrt(-x) >= 0", 1, 2), Truth::False);
  EXPECT_EQ(truth_on("x + 0*x >= 0", 1, 2), Truth::True);
}

TEST(ConstraintTruth, AtomEnclosuresContainPointValues) {
  // The joint-limit atom (A' - P).(B' - P) of rrrrr_joint_limit.robot, evaluated
  // independently in long double at random points of random boxes.
  set_working_precision(53);
  Model m = load_model(robot_path("rrrrr_joint_limit.robot"));
  ModelEvaluator ev(m);
  ASSERT_EQ(m.constraint_atoms.size(), 1u);
  int g = m.constraint_atoms[0];
  std::vector<int> prog = m.dag.closure({g});
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> U(0, 1);
  double lo[4] = {-20, -20, -3.14, -3.14}, hi[4] = {20, 20, 3.14, 3.14};
  for (int trial = 0; trial < 2000; ++trial) {
    Box b(4);
    double p[4];
    for (int v = 0; v < 4; ++v) {
      double c = lo[v] + (hi[v] - lo[v]) * U(gen), w = std::ldexp(U(gen), -int(U(gen) * 20));
      b[v].set_hull(c - w, c + w);
      p[v] = c - w + 2 * w * U(gen);
      p[v] = std::min(std::max(p[v], c - w), c + w);
    }
    ev.nodes(prog, b);
    const Interval& enc = ev.value(g);
    long double a1x = 8 * std::cos((long double)p[2]), a1y = 8 * std::sin((long double)p[2]);
    long double b1x = 9 + 5 * std::cos((long double)p[3]), b1y = 5 * std::sin((long double)p[3]);
    long double val = (a1x - p[0]) * (b1x - p[0]) + (a1y - p[1]) * (b1y - p[1]);
    // long double is ~1e-19 relative: compare with a margin far below the widths used.
    ASSERT_GE((double)val + 1e-9 * (1 + std::fabs((double)val)), enc.lo_down()) << trial;
    ASSERT_LE((double)val - 1e-9 * (1 + std::fabs((double)val)), enc.hi_up()) << trial;
  }
}

namespace {

// Independent geometry (double precision, with a margin that skips near-ties).
struct Pt {
  double x, y;
};
Pt operator-(Pt a, Pt b) { return {a.x - b.x, a.y - b.y}; }
double cross(Pt a, Pt b) { return a.x * b.y - a.y * b.x; }
double dot(Pt a, Pt b) { return a.x * b.x + a.y * b.y; }

// +1: segments certainly disjoint, -1: certainly intersect, 0: too close to call.
int segments_disjoint(Pt t, Pt u, Pt v, Pt w) {
  double d1 = cross(u - t, v - t), d2 = cross(u - t, w - t);
  double d3 = cross(w - v, t - v), d4 = cross(w - v, u - v);
  const double tie = 1e-7;
  if (std::fabs(d1) < tie || std::fabs(d2) < tie || std::fabs(d3) < tie || std::fabs(d4) < tie)
    return 0;
  bool cross_both = (d1 > 0) != (d2 > 0) && (d3 > 0) != (d4 > 0);
  return cross_both ? -1 : 1;
}

// Distance from c to segment [t,u], by projection clamped to the segment.
double segment_distance(Pt c, Pt t, Pt u) {
  Pt d = u - t;
  double s = std::clamp(dot(c - t, d) / dot(d, d), 0.0, 1.0);
  Pt f{t.x + s * d.x, t.y + s * d.y};
  return std::hypot(c.x - f.x, c.y - f.y);
}

struct Joints {
  Pt A, A1, P, B, B1;
};
Joints joints(const double* p) {
  return {{0, 0}, {8 * std::cos(p[2]), 8 * std::sin(p[2])}, {p[0], p[1]}, {9, 0},
          {9 + 5 * std::cos(p[3]), 5 * std::sin(p[3])}};
}

// -1 violated, +1 satisfied, 0 too close to call.
int collisions_ok(const double* p) {
  Joints j = joints(p);
  int a = segments_disjoint(j.A, j.A1, j.B, j.B1), b = segments_disjoint(j.A, j.A1, j.B1, j.P),
      c = segments_disjoint(j.A1, j.P, j.B, j.B1);
  if (a < 0 || b < 0 || c < 0) return -1;
  return (a == 0 || b == 0 || c == 0) ? 0 : 1;
}
int joint_limit_ok(const double* p) {
  Joints j = joints(p);
  double d = dot(j.A1 - j.P, j.B1 - j.P);
  return std::fabs(d) < 1e-7 ? 0 : d > 0 ? 1 : -1;
}
int obstacle_ok(const double* p) {
  Joints j = joints(p);
  Pt c{4.5, 0};
  double d = std::min({segment_distance(c, j.A, j.A1), segment_distance(c, j.A1, j.P),
                       segment_distance(c, j.B, j.B1), segment_distance(c, j.B1, j.P)});
  return std::fabs(d - 1) < 1e-7 ? 0 : d > 1 ? 1 : -1;
}

struct ConstrainedCase {
  const char* file;
  int (*ok)(const double*);
};

void PrintTo(const ConstrainedCase& c, std::ostream* os) { *os << c.file; }

class InnerTest : public ::testing::TestWithParam<ConstrainedCase> {};

}  // namespace

TEST_P(InnerTest, SolutionBoxesSatisfyTheConstraintEverywhere) {
  const ConstrainedCase c = GetParam();
  set_working_precision(53);
  Model m = load_model(robot_path(c.file));
  AspectsConfig cfg;
  cfg.eps = 0.5;
  AspectsResult r = compute_aspects(m, cfg);
  ASSERT_GT(r.solutions, 0);
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> U(0, 1);
  long sampled = 0, boundary = 0;
  for (int b = 0; b < r.boxes.size(); ++b) {
    if (!r.boxes.certified(b)) {
      boundary += r.boxes.kind(b) == UndecidedKind::Constraint;
      continue;
    }
    for (int s = 0; s < 8; ++s) {
      double p[4];
      for (int v = 0; v < 4; ++v)
        p[v] = r.boxes.lo(b, v) + (r.boxes.hi(b, v) - r.boxes.lo(b, v)) * U(gen);
      int ok = c.ok(p);
      ASSERT_NE(ok, -1) << c.file << ": solution box " << b << " holds a violating point";
      sampled += ok != 0;
    }
  }
  EXPECT_GT(sampled, 100);
  EXPECT_GT(boundary, 0);  // the constraint's boundary is reported apart (blue boxes)
}

INSTANTIATE_TEST_SUITE_P(Rrrrr, InnerTest,
                         ::testing::Values(ConstrainedCase{"rrrrr_collisions.robot", collisions_ok},
                                           ConstrainedCase{"rrrrr_joint_limit.robot", joint_limit_ok},
                                           ConstrainedCase{"rrrrr_obstacle.robot", obstacle_ok}),
                         [](const auto& info) {
                           std::string s = info.param.file;
                           return s.substr(6, s.find('.') - 6);
                         });

namespace {
AspectsResult solve_counts(const char* file, double eps) {
  set_working_precision(53);
  Model m = load_model(robot_path(file));
  AspectsConfig cfg;
  cfg.eps = eps;
  cfg.threads = 2;
  return compute_aspects(m, cfg);
}
}  // namespace

TEST(ConstrainedCounts, CollisionFreeRrrrrAtEps01) {
  AspectsResult r = solve_counts("rrrrr_collisions.robot", 0.1);
  EXPECT_EQ(r.filtered, 10);  // paper 5.4.1: ten collision-free CSNCs
  EXPECT_EQ(r.separation.lower_bound, 10);
}

TEST(ConstrainedCounts, JointLimitedRrrrrAtEps01) {
  AspectsResult r = solve_counts("rrrrr_joint_limit.robot", 0.1);
  // Paper 5.4.2: twelve joint-limited CSNCs. The certified bound reaches 12; the
  // size-ratio heuristic keeps two more (a pair of 479-box CSNCs, cut from larger ones
  // of the same sign class by undecided boxes): see the closing note of issue 5.
  EXPECT_EQ(r.separation.lower_bound, 12);
  EXPECT_EQ(r.filtered, 14);
}

TEST(ConstrainedCounts, ObstacleFreeRrrrrAtEps005) {
  AspectsResult r = solve_counts("rrrrr_obstacle.robot", 0.05);
  // Paper 5.4.3: 26 obstacle-free CSNCs; the certified bound reaches 26 at eps = 0.05
  // (24 at eps = 0.1), the size-ratio heuristic keeps 24 of them.
  EXPECT_EQ(r.separation.lower_bound, 26);
  EXPECT_EQ(r.filtered, 24);
}
