// "One pose, two commands" witnesses (paper 3.2) on hand-made boxes: found inside one CSNC
// only, with disjoint commands (modulo 2π on a periodic command), through the seam of a
// periodic pose; and none on PRRP, whose aspects hold one command per pose.
#include <gtest/gtest.h>

#include <string>

#include "cuspidality.h"
#include "generalized_aspects.h"
#include "model.h"

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

TEST(PoseWitnesses, NoneOnPrrp) {
  set_working_precision(53);
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/prrp.robot");
  AspectsConfig cfg;
  cfg.eps = 0.1;
  AspectsResult r = compute_aspects(m, cfg);
  ASSERT_EQ(r.csnc_sizes.size(), 4u);
  EXPECT_TRUE(r.cuspidal.pose.empty());
  EXPECT_EQ(r.cuspidal.count, (std::vector<int64_t>(4, 0)));
}
