// "One pose, two commands" witnesses (paper 3.2) on hand-made boxes: found inside one CSNC
// only, with disjoint commands (modulo 2π on a periodic command), through the seam of a
// periodic pose; and none on PRRP, whose aspects hold one command per pose.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <utility>

#include "aspects/cuspidality.h"
#include "generalized_aspects.h"
#include "model/model.h"

using namespace aspects;

namespace {

// Boxes over (x, q): x pose, q command.
BoxStore boxes(const std::vector<std::vector<double>>& xq) {
  BoxStore R(2);
  for (const auto& b : xq) R.push({Interval(b[0], b[1]), Interval(b[2], b[3])});
  return R;
}

WitnessSpace space(bool x_periodic, bool q_periodic) {
  return WitnessSpace({0}, {1}, {x_periodic, q_periodic});
}

}  // namespace

TEST(PoseWitnesses, SameCsncOverlappingPosesDisjointCommands) {
  set_working_precision(53);
  // 0 and 2 share poses [0.5, 1] with commands apart: a witness. 1 overlaps 0 in q.
  // 3 is in another CSNC. 4 has poses apart from 0.
  BoxStore R = boxes({{0, 1, 0, 1}, {0, 1, 0.5, 2}, {0.5, 2, 3, 4}, {0, 1, 5, 6},
                      {3, 4, 5, 6}});
  CuspidalWitnesses w = find_pose_witnesses(R, {0, 0, 0, 1, 0}, 2, space(false, false));
  ASSERT_EQ(w.pose.size(), 2u);
  EXPECT_EQ(w.pose[0].a, 0);
  EXPECT_EQ(w.pose[0].b, 2);
  EXPECT_EQ(w.pose[1].a, 1);
  EXPECT_EQ(w.pose[1].b, 2);
  EXPECT_EQ(w.count, (std::vector<int64_t>{2, 0}));
  EXPECT_EQ(w.search[0], WitnessSearch::Complete);
}

TEST(PoseWitnesses, PeriodicCommandsDisjointOnlyModuloTwoPi) {
  set_working_precision(53);
  // q in [3, 3.2] and [-3.2, -3] + 2π = [3.08.., 3.28..]: the same angles, no witness.
  // q in [0, 1] and [3, 3.2]: disjoint on the circle, a witness.
  BoxStore R = boxes({{0, 1, 3, 3.2}, {0, 1, -3.2, -3}, {0, 1, 0, 1}});
  CuspidalWitnesses w = find_pose_witnesses(R, {0, 0, 0}, 1, space(false, true));
  ASSERT_EQ(w.pose.size(), 2u);
  EXPECT_EQ(w.pose[0].a, 0);
  EXPECT_EQ(w.pose[0].b, 2);
  EXPECT_EQ(w.pose[1].a, 1);
  EXPECT_EQ(w.pose[1].b, 2);
  // Without periodicity the first pair is a witness too.
  EXPECT_EQ(find_pose_witnesses(R, {0, 0, 0}, 1, space(false, false)).pose.size(), 3u);
}

TEST(PoseWitnesses, PosesMeetAcrossTheSeam) {
  set_working_precision(53);
  // x near π in box 0 and near -π in box 1: they meet with box 1 shifted by +2π.
  BoxStore R = boxes({{3.1, 3.2, 0, 1}, {-3.2, -3.1, 2, 3}});
  CuspidalWitnesses w = find_pose_witnesses(R, {0, 0}, 1, space(true, false));
  ASSERT_EQ(w.pose.size(), 1u);
  EXPECT_EQ(w.pose[0].shift(0), 1);
  EXPECT_EQ(w.pose[0].shift(1), 0);
  EXPECT_TRUE(poses_overlap(R, 0, 1, {1, 0}, space(true, false)));
  EXPECT_FALSE(poses_overlap(R, 0, 1, {0, 0}, space(true, false)));
  // Not periodic: the poses are apart.
  EXPECT_TRUE(find_pose_witnesses(R, {0, 0}, 1, space(false, false)).pose.empty());
}

TEST(PoseWitnesses, CapStopsTheSearch) {
  set_working_precision(53);
  BoxStore R = boxes({{0, 1, 0, 1}, {0, 1, 2, 3}, {0, 1, 4, 5}, {0, 1, 6, 7}});
  CuspidalWitnesses w = find_pose_witnesses(R, {0, 0, 0, 0}, 1, space(false, false), 2);
  EXPECT_EQ(w.count[0], 2);
  EXPECT_EQ(w.search[0], WitnessSearch::Capped);
}

// PRRP has neither kind of witness (one solve checks both searches).
TEST(CuspidalWitnesses, NoneOfEitherKindOnPrrp) {
  set_working_precision(53);
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/prrp.robot");
  AspectsConfig cfg;
  cfg.eps = 0.1;
  AspectsResult r = compute_aspects(m, cfg);
  ASSERT_EQ(r.csnc_sizes.size(), 4u);
  EXPECT_TRUE(r.cuspidal.pose.empty());
  EXPECT_EQ(r.cuspidal.count, (std::vector<int64_t>(4, 0)));
  EXPECT_TRUE(r.cuspidal.command.empty());
  EXPECT_EQ(r.cuspidal.command_count, (std::vector<int64_t>(4, 0)));
}

// "One command, two poses": the candidates offered to the proof are the pairs of one CSNC
// whose commands meet (modulo 2π on a periodic command) and whose poses are apart.
TEST(CommandWitnesses, CandidatesMeetInCommandsApartInPoses) {
  set_working_precision(53);
  // Over (x, q): 0 and 2 share commands [0.5, 1] with poses apart: a candidate; 1 meets 0
  // in x; 3 is in another CSNC; 4 has commands apart from 0; 5 meets 0 in q modulo 2π.
  const double t = 2 * M_PI;
  BoxStore R = boxes({{0, 1, 0, 1}, {0.5, 2, 0, 1}, {3, 4, 0.5, 2}, {5, 6, 0, 1},
                      {5, 6, 3, 4}, {7, 8, 0.5 + t, 0.9 + t}});
  std::vector<std::pair<int, int>> offered;
  auto prove = [&](CommandWitness& w) {
    offered.emplace_back(w.a, w.b);
    return w.a == 0;  // "proved" only for pairs with box 0
  };
  CuspidalWitnesses w;
  find_command_witnesses(R, {0, 0, 0, 1, 0, 0}, 2, space(false, true), prove, w);
  std::sort(offered.begin(), offered.end());
  EXPECT_EQ(offered, (std::vector<std::pair<int, int>>{{0, 2}, {0, 5}, {1, 2}, {1, 5}, {2, 5}}));
  ASSERT_EQ(w.command.size(), 2u);
  EXPECT_EQ(w.command[1].b, 5);
  EXPECT_EQ(w.command[1].shift(1), -1);  // box 5 − 2π meets box 0 in q
  EXPECT_EQ(w.command_count, (std::vector<int64_t>{2, 0}));
}

// The proof attempts of a CSNC are at most max(attempts / 10, attempts_per_box × its
// boxes): four boxes with the same commands and poses apart make six candidates, of which
// a budget of one per box (floor 4) proves the first four in sweep order and says Capped;
// two per box prove all six.
TEST(CommandWitnesses, AttemptBudgetFollowsTheCsncSize) {
  set_working_precision(53);
  BoxStore R = boxes({{0, 1, 0, 1}, {2, 3, 0, 1}, {4, 5, 0, 1}, {6, 7, 0, 1}});
  int offered = 0;
  auto prove = [&](CommandWitness&) {
    ++offered;
    return false;
  };
  CuspidalWitnesses w;
  find_command_witnesses(R, {0, 0, 0, 0}, 1, space(false, false), prove, w, 1000, 40, 1);
  EXPECT_EQ(offered, 4);
  EXPECT_EQ(w.command_search[0], WitnessSearch::Capped);
  offered = 0;
  find_command_witnesses(R, {0, 0, 0, 0}, 1, space(false, false), prove, w, 1000, 40, 2);
  EXPECT_EQ(offered, 6);
  EXPECT_EQ(w.command_search[0], WitnessSearch::Complete);
}

namespace {

AspectsResult solve_text(const std::string& text, double eps) {
  Model m = parse_model(text, "toy");
  AspectsConfig cfg;
  cfg.eps = eps;
  return compute_aspects(m, cfg);
}

}  // namespace

// The squaring map of the complex plane: q = x² sends x and −x to the same command, and
// det Fx = 4|x|² ≠ 0 off the origin, so the punctured square is one aspect holding two poses
// per command. Every solution box has a partner around −x (some have two or three).
TEST(CommandWitnesses, ComplexSquaringHasTwoPosesPerCommand) {
  set_working_precision(53);
  AspectsResult r = solve_text(
      "robot COMPLEX_SQUARE\npose x1 in [-2, 2]\npose x2 in [-2, 2]\n"
      "command q1 in [-5, 5]\ncommand q2 in [-9, 9]\n"
      "equation x1*x1 - x2*x2 - q1 = 0\nequation 2*x1*x2 - q2 = 0\n", 0.3);
  ASSERT_EQ(r.csnc_sizes.size(), 1u);
  EXPECT_EQ(r.solutions, 80);
  EXPECT_EQ(r.cuspidal.command.size(), 116u);
  EXPECT_EQ(r.cuspidal.command_count, (std::vector<int64_t>{116}));
  std::vector<bool> has(r.boxes.size(), false);
  for (const CommandWitness& w : r.cuspidal.command) has[w.a] = has[w.b] = true;
  for (int b = 0; b < r.boxes.size(); ++b) EXPECT_EQ(has[b], bool(r.boxes.certified(b))) << b;
  EXPECT_EQ(r.cuspidal.command_search[0], WitnessSearch::Complete);
  EXPECT_TRUE(r.cuspidal.pose.empty());
  for (const CommandWitness& w : r.cuspidal.command) {
    // The two iterates enclose x and −x: on each pose they are symmetric about 0.
    for (int j = 0; j < 2; ++j) {
      EXPECT_LE(w.xa[j].lo_down(), -w.xb[j].lo_down() + 1e-6);
      EXPECT_GE(w.xa[j].hi_up(), -w.xb[j].hi_up() - 1e-6);
    }
  }
}

// x = q/2 and q/2 + π on the torus: both CSNCs (2x − q ≡ 0 and ≡ π) hold two poses for
// every command, proved across the seams of x and q.
TEST(CommandWitnesses, DoublePoseOnTheTorus) {
  set_working_precision(53);
  AspectsResult r = solve_text(
      "robot DOUBLE_POSE\npose    x in [-pi, pi] periodic\n"
      "command q in [-pi, pi] periodic\nequation sin(x + x - q) = 0\n", 0.3);
  ASSERT_EQ(r.csnc_sizes.size(), 2u);
  EXPECT_EQ(r.cuspidal.command_count, (std::vector<int64_t>{57, 29}));
  int shifted = 0;
  for (const CommandWitness& w : r.cuspidal.command) shifted += w.shift(1) != 0;
  EXPECT_GT(shifted, 0);
}

// With two non-periodic pose coordinates the sweep lists its candidates strip by strip
// (core/aspects/cuspidality.cpp): on random boxes the witnesses found are exactly the pairs of one
// CSNC that meet on every pose coordinate and are apart on a command, each once.
TEST(PoseWitnesses, StripsFindEveryPairOnRandomBoxes) {
  set_working_precision(53);
  std::mt19937 g(5);
  std::uniform_real_distribution<double> U(0, 1);
  // Pose (x, y, t), t periodic but within [-1, 1] (no shift by 2π can matter); commands
  // (q1, q2). Widths from 0 (points) to wide boxes spanning many strips.
  const int n = 3000;
  BoxStore R(5);
  std::vector<int32_t> csnc(n);
  for (int i = 0; i < n; ++i) {
    Box b(5);
    for (int v = 0; v < 5; ++v) {
      const double range = v == 2 ? 2 : 10, lo0 = v == 2 ? -1 : 0;
      double w = U(g) < 0.05 ? range * U(g) : U(g) < 0.1 ? 0 : 0.3 * U(g);
      double c = lo0 + range * U(g);
      double lo = std::max(lo0, c - w / 2), hi = std::min(lo0 + range, c + w / 2);
      b[v] = Interval(lo, hi);
    }
    R.push(b);
    csnc[i] = int32_t(g() % 3);
  }
  const WitnessSpace s({0, 1, 2}, {3, 4}, {false, false, true, false, false});
  CuspidalWitnesses w = find_pose_witnesses(R, csnc, 3, s, 1000000);
  std::set<std::pair<int, int>> got, want;
  for (const PoseWitness& p : w.pose) {
    EXPECT_TRUE(got.insert({p.a, p.b}).second) << "listed twice";
    EXPECT_EQ(p.shift_code, pack_shift({0, 0, 0, 0, 0}));
  }
  auto meets = [&](int a, int b, int v) {
    return std::max(R.lo(a, v), R.lo(b, v)) <= std::min(R.hi(a, v), R.hi(b, v));
  };
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      if (csnc[a] == csnc[b] && meets(a, b, 0) && meets(a, b, 1) && meets(a, b, 2) &&
          (!meets(a, b, 3) || !meets(a, b, 4)))
        want.insert({a, b});
  EXPECT_EQ(got, want);
  EXPECT_GT(want.size(), 1000u);  // not vacuous
  int64_t total = 0;
  for (int64_t c : w.count) total += c;
  EXPECT_EQ(total, int64_t(w.pose.size()));
}
