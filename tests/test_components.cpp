// Paper 4.4.1 and 4.4.2 on hand-made graphs: components by decreasing size, the
// filtering rule with its tie rule, and the separation bound (11).
#include <gtest/gtest.h>

#include "aspects/components.h"
#include "aspects/separation.h"

using namespace aspects;

TEST(Components, NumberedByDecreasingSize) {
  // 0-1-2 | 3 | 4-5
  Components c = connected_components(6, {{0, 1}, {1, 2}, {4, 5}});
  ASSERT_EQ(c.sizes, (std::vector<int64_t>{3, 2, 1}));
  EXPECT_EQ(c.of[0], 0);
  EXPECT_EQ(c.of[2], 0);
  EXPECT_EQ(c.of[4], 1);
  EXPECT_EQ(c.of[3], 2);
}

TEST(Filtering, CutsAtLargestRatio) {
  EXPECT_EQ(filter_components({1000, 900, 800, 20, 10, 5}), 3);
  EXPECT_EQ(filter_components({50, 5, 4, 1}), 1);
}

TEST(Filtering, KeepsEqualSizedComponents) {
  EXPECT_EQ(filter_components({7, 7, 7, 7}), 4);  // PRRP: every ratio is 1
  EXPECT_EQ(filter_components({10, 9}), 2);       // largest ratio below 2
  EXPECT_EQ(filter_components({}), 0);
  EXPECT_EQ(filter_components({3}), 1);
}

TEST(Separation, CountsComponentsPerSignClass) {
  // One factor. Boxes 0,1 (+, certified), 2 (0, undecided), 3,4 (−, certified).
  std::vector<int8_t> signs = {1, 1, 0, -1, -1};
  std::vector<uint8_t> cert = {1, 1, 0, 1, 1};
  std::vector<NeighborPair> M = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 4, 0}};
  SeparationResult s = separate_by_signs(5, 1, signs, cert, M);
  EXPECT_EQ(s.lower_bound, 2);
  // Cut the + side in two: the bound grows to 3.
  M = {{1, 2, 0}, {2, 3, 0}, {3, 4, 0}};
  EXPECT_EQ(separate_by_signs(5, 1, signs, cert, M).lower_bound, 3);
}

TEST(Separation, AmbiguousCertifiedBoxCountsInNoClass) {
  // A certified box whose factor enclosure straddles 0 must not be counted in both
  // classes (it would count one aspect twice).
  std::vector<int8_t> signs = {0};
  std::vector<uint8_t> cert = {1};
  EXPECT_EQ(separate_by_signs(1, 1, signs, cert, {}).lower_bound, 0);
}

TEST(Separation, UndecidedBoxesJoinComponentsOfBothClasses) {
  // + certified, 0 undecided, + certified: one component of the + class.
  std::vector<int8_t> signs = {1, 0, 1};
  std::vector<uint8_t> cert = {1, 0, 1};
  std::vector<NeighborPair> M = {{0, 1, 0}, {1, 2, 0}};
  EXPECT_EQ(separate_by_signs(3, 1, signs, cert, M).lower_bound, 1);
}

TEST(Separation, RepresentativesAreTheLargestCsncOfEachCountedComponent) {
  // + class: boxes 0,1 (CSNC 0) and 2 (CSNC 2) joined through the undecided box 3;
  // − class: box 4 (CSNC 1) alone.
  std::vector<int8_t> signs = {1, 1, 1, 0, -1};
  std::vector<uint8_t> cert = {1, 1, 1, 0, 1};
  std::vector<int32_t> csnc = {0, 0, 2, -1, 1};
  std::vector<NeighborPair> M = {{0, 1, 0}, {1, 3, 0}, {2, 3, 0}, {3, 4, 0}};
  SeparationResult s = separate_by_signs(5, 1, signs, cert, M, &csnc);
  EXPECT_EQ(s.lower_bound, 2);
  EXPECT_EQ(s.representatives, (std::vector<int32_t>{0, 1}));  // CSNC 2 shares with 0
}
