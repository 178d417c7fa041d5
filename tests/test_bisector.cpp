// Bisectors (core/search/bisector.*): every policy keeps the paper's meaning of eps — a box is
// bisected while (and only while) its widest variable is wider than eps — and splits at a
// double strictly inside the chosen variable. Then each policy's own choice.
// Break it to see it fail: make Bisector::choose test `>= eps_` (a box exactly eps wide is
// then split), or return `box[v].lo_down()` as the split point.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "search/bisector.h"
#include "model/model.h"

using namespace aspects;

namespace {

// Two pose variables (x, y), two commands (a, b); model order x, a, y, b.
const char* kModel =
    "robot T\n"
    "pose x in [0, 8]\n"
    "command a in [0, 8]\n"
    "pose y in [0, 8]\n"
    "command b in [0, 8]\n"
    "equation x - a = 0\n"
    "equation y - b = 0\n";

Box make_box(std::initializer_list<std::pair<double, double>> iv) {
  Box b;
  for (auto [lo, hi] : iv) b.emplace_back(lo, hi);
  return b;
}

const BisectorKind kAll[] = {BisectorKind::RoundRobin, BisectorKind::PoseFirst,
                             BisectorKind::Verdict};

TEST(Bisector, KeepsTheMeaningOfEpsAndSplitsInside) {
  set_working_precision(53);
  Model m = parse_model(kModel, "t.robot");
  const double eps = 0.25;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> lo(0, 4), logw(-4, 1);
  const Verdict verdicts[] = {Verdict::NoExistence, Verdict::SingularFx, Verdict::SingularFq};
  for (BisectorKind kind : kAll) {
    auto bis = make_bisector(kind, m, eps);
    for (int i = 0; i < 5000; ++i) {
      Box b;
      double widest = 0;
      for (int v = 0; v < 4; ++v) {
        double l = lo(rng), w = std::pow(2.0, logw(rng));
        if (i % 7 == 0) w = eps;  // exactly eps wide: not to be split
        b.emplace_back(l, l + w);
        widest = std::max(widest, b.back().width_up());
      }
      SplitContext ctx{int(i % 5) - 1, verdicts[i % 3]};
      SplitChoice c = bis->choose(b, ctx);
      if (widest <= eps) {
        ASSERT_EQ(c.var, -1) << "a box at most eps wide is a leaf";
        continue;
      }
      ASSERT_GE(c.var, 0);
      ASSERT_GT(b[c.var].width_up(), eps) << "only a variable wider than eps is cut";
      ASSERT_GT(c.at, b[c.var].lo_down());
      ASSERT_LT(c.at, b[c.var].hi_up());
    }
  }
}

// With eps below the doubles' spacing (eps 1e-300, a cell near 1), a variable
// one ulp wide is still wider than eps, but no double lies strictly inside it. Cut at its
// middle rounded to an end, the box had a child equal to itself, again and again: a tree
// tens of thousands of levels deep, and a certificate check_cert rejected ("bisection point
// not strictly inside the cell"). Such a variable is never cut; a box of nothing else is a
// leaf.
TEST(Bisector, AVariableWithNoDoubleInsideIsNotCut) {
  set_working_precision(53);
  Model m = parse_model(kModel, "t.robot");
  const double eps = 1e-300, one_up = std::nextafter(1.0, 2.0);
  const double two_up = std::nextafter(one_up, 2.0);
  EXPECT_FALSE(splittable(Interval(1.0, one_up), eps));
  EXPECT_TRUE(splittable(Interval(1.0, two_up), eps));  // one_up is inside
  EXPECT_FALSE(splittable(Interval(1.0, two_up), 1.0));  // at most eps wide
  for (BisectorKind kind : kAll) {
    auto bis = make_bisector(kind, m, eps);
    // x (pose) and b (command) one ulp wide, a and y wide: a or y is cut, inside.
    const Box some = make_box({{1, one_up}, {0, 8}, {0, 8}, {1, one_up}});
    for (int parent = -1; parent < 4; ++parent)
      for (Verdict verdict : {Verdict::NoExistence, Verdict::SingularFx}) {
        const SplitChoice c = bis->choose(some, {parent, verdict});
        ASSERT_TRUE(c.var == 1 || c.var == 2) << "cut " << c.var << " after " << parent;
        EXPECT_EQ(c.at, 4.0);
      }
    // Every variable one ulp wide: a leaf.
    const Box none = make_box({{1, one_up}, {-one_up, -1}, {0x1p-40, std::nextafter(0x1p-40, 1.0)},
                               {1, one_up}});
    EXPECT_EQ(bis->choose(none, {0, Verdict::SingularFx}).var, -1);
    // Three doubles: the middle one is the cut.
    const SplitChoice c = bis->choose(make_box({{1, two_up}, {1, one_up}, {1, one_up}, {1, one_up}}),
                                      {-1, Verdict::NoExistence});
    EXPECT_EQ(c.var, 0);
    EXPECT_EQ(c.at, one_up);
  }
}

TEST(Bisector, RoundRobinCutsTheNextWideVariableAfterTheParent) {
  Model m = parse_model(kModel, "t.robot");
  auto bis = make_bisector(BisectorKind::RoundRobin, m, 0.5);
  Box b = make_box({{0, 1}, {0, 0.5}, {0, 1}, {0, 1}});  // a (index 1) is not wider than eps
  EXPECT_EQ(bis->choose(b, {-1, Verdict::NoExistence}).var, 0);  // the root: first variable
  EXPECT_EQ(bis->choose(b, {0, Verdict::NoExistence}).var, 2);   // skips a
  EXPECT_EQ(bis->choose(b, {2, Verdict::NoExistence}).var, 3);
  EXPECT_EQ(bis->choose(b, {3, Verdict::NoExistence}).var, 0);   // wraps around
}

TEST(Bisector, PoseFirstCutsTheWidestPoseThenTheWidestCommand) {
  Model m = parse_model(kModel, "t.robot");
  auto bis = make_bisector(BisectorKind::PoseFirst, m, 0.5);
  EXPECT_EQ(bis->choose(make_box({{0, 1}, {0, 8}, {0, 2}, {0, 1}}), {}).var, 2);  // y
  EXPECT_EQ(bis->choose(make_box({{0, 0.5}, {0, 8}, {0, 0.5}, {0, 9}}), {}).var, 3);  // b
}

TEST(Bisector, VerdictCutsThePoseWhereItBlockedTheProofAndIsRoundRobinOtherwise) {
  Model m = parse_model(kModel, "t.robot");
  auto bis = make_bisector(BisectorKind::Verdict, m, 0.5);
  Box b = make_box({{0, 1}, {0, 8}, {0, 2}, {0, 4}});
  EXPECT_EQ(bis->choose(b, {0, Verdict::SingularFx}).var, 2);   // widest pose: y
  EXPECT_EQ(bis->choose(b, {0, Verdict::SingularFq}).var, 2);
  EXPECT_EQ(bis->choose(b, {0, Verdict::WidePose}).var, 2);
  EXPECT_EQ(bis->choose(b, {0, Verdict::NoExistence}).var, 1);  // round robin after x: a
}

TEST(Bisector, NamesParse) {
  BisectorKind k = BisectorKind::RoundRobin;
  EXPECT_TRUE(parse_bisector_kind("pose-first", k));
  EXPECT_EQ(k, BisectorKind::PoseFirst);
  EXPECT_TRUE(parse_bisector_kind("verdict", k));
  EXPECT_EQ(k, BisectorKind::Verdict);
  EXPECT_TRUE(parse_bisector_kind("round-robin", k));
  EXPECT_EQ(k, BisectorKind::RoundRobin);
  EXPECT_FALSE(parse_bisector_kind("smear", k));
  EXPECT_FALSE(parse_bisector_kind("", k));
}

}  // namespace

// The model language lists the names a `bisect` statement may give; the search must
// give every one of them a bisector, and accept no other name.
TEST(Bisector, EveryNameOfTheLanguageHasABisector) {
  for (const char* name : kBisectNames) {
    BisectorKind kind;
    EXPECT_TRUE(parse_bisector_kind(name, kind)) << name;
  }
  BisectorKind kind;
  EXPECT_FALSE(parse_bisector_kind("widest", kind));
  EXPECT_EQ(std::size(kBisectNames), std::size(kAll));
}
