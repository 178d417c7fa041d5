// P3 alone (proofs/link.*): certified links between two solution boxes of sin(q) = x with
// q periodic in [-π, π], against the exact solutions q = π − asin(x) (mod 2π) near the seam
// (MPFR at 256 bits):
//  - boxes meeting across the ±π seam are linked with the shift +2π, and with −2π when
//    the pair is taken the other way round; the wrong shift links nothing;
//  - boxes that meet but share no solution are never linked (constructed and random).
//
// Seen failing (each break made in proofs/link.cpp, then reverted):
//  - certify_link without its last check (the proved enclosure inside [q_A] ∩ [q_B]):
//    DisjointSolutionsAreNeverLinked and RandomPairsAgreeWithTheExactSolutions fail;
//  - inner_intersection shifting b by −2πk instead of 2πk: SeamIsCrossedWithPlusTwoPi,
//    SeamIsCrossedWithMinusTwoPi and RandomPairsAgreeWithTheExactSolutions fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "link.h"
#include "model/model.h"
#include "model/model_eval.h"
#include "test_util.h"

using namespace aspects;
using aspects_test::interval_contains;
using aspects_test::interval_str;
using aspects_test::R;

namespace {

const char* const kSeamModel =
    "robot Seam\n"
    "pose x in [-1, 1]\n"
    "command q in [-pi, pi] periodic\n"
    "equation sin(q) - x = 0\n";

// Variables in model order: x, then q.
Box box(double xlo, double xhi, double qlo, double qhi) {
  return {Interval(xlo, xhi), Interval(qlo, qhi)};
}

// The solution near the seam at the pose x, as a real number in (π/2, 3π/2).
R seam_root(double x) {
  R r;
  mpfr_asin(r.get(), R(x).get(), MPFR_RNDN);
  return R::pi() - r;
}

// 2π·k exactly enough (256 bits).
R two_pi(int k) { return R(2 * k) * R::pi(); }

class Link : public ::testing::Test {
 protected:
  void SetUp() override {
    set_working_precision(53);
    aspects_test::ref_prec() = 256;
    model_ = parse_model(kSeamModel, "seam");
    ev_ = std::make_unique<ModelEvaluator>(model_);
  }

  bool link(const Box& a, const Box& b, int shift, LinkProof& proof) {
    BoxStore store(2);
    store.push(a);
    store.push(b);
    NeighborPair pair{0, 1, pack_shift({0, shift})};
    HsWorkspace ws;
    return certify_link(*ev_, store, pair, 1.01, proof, ws);
  }

  Model model_;
  std::unique_ptr<ModelEvaluator> ev_;
};

}  // namespace

TEST_F(Link, SeamIsCrossedWithPlusTwoPi) {
  Box a = box(-0.2, 0.0, 2.9, 3.3), b = box(-0.1, 0.1, -3.3, -2.9);
  LinkProof p;
  ASSERT_TRUE(link(a, b, +1, p));
  ASSERT_EQ(p.witness.size(), 1u);
  R root = seam_root(p.witness[0]);  // in a, and in b + 2π
  EXPECT_TRUE(interval_contains(p.existence.image[0], root)) << interval_str(p.existence.image[0]);
  EXPECT_TRUE(interval_contains(a[1], root));
  EXPECT_TRUE(interval_contains(b[1], root - two_pi(1)));
  EXPECT_TRUE(p.common[0].contains(p.existence.image[0]));
  LinkProof q;
  EXPECT_FALSE(link(a, b, 0, q));   // without the shift the commands do not meet
  EXPECT_FALSE(link(a, b, -1, q));  // nor with the wrong one
}

TEST_F(Link, SeamIsCrossedWithMinusTwoPi) {
  Box a = box(-0.1, 0.1, -3.3, -2.9), b = box(-0.2, 0.0, 2.9, 3.3);
  LinkProof p;
  ASSERT_TRUE(link(a, b, -1, p));
  R root = seam_root(p.witness[0]) - two_pi(1);  // in a, and in b − 2π
  EXPECT_TRUE(interval_contains(p.existence.image[0], root)) << interval_str(p.existence.image[0]);
  EXPECT_TRUE(interval_contains(a[1], root));
  EXPECT_TRUE(interval_contains(b[1], root + two_pi(1)));
  LinkProof q;
  EXPECT_FALSE(link(a, b, +1, q));
  EXPECT_FALSE(link(a, b, 0, q));
}

TEST_F(Link, DisjointSolutionsAreNeverLinked) {
  // The boxes meet in x = -0.1, q ∈ [3.24178, 3.3] (c + 2π), but the solution there is
  // q = π + asin(0.1) ≈ 3.2417601: no point of both boxes solves the equation. Iteration
  // (9) at the witness proves that solution in an enclosure that overlaps the common part:
  // only the last check of certify_link stands between it and a false link.
  Box a = box(-0.2, -0.1, 2.9, 3.3), c = box(-0.1, 0.1, -3.041405307179586, -2.9);
  R root = seam_root(-0.1), common_lo = R(c[1].lo_down()) + two_pi(1);
  ASSERT_TRUE(root < common_lo) << root.str() << " " << common_lo.str();
  LinkProof p;
  EXPECT_FALSE(link(a, c, +1, p));
  ASSERT_EQ(p.witness.size(), 1u);
  EXPECT_EQ(p.witness[0], -0.1);
  ASSERT_EQ(p.existence.image.size(), 1u);  // proved...
  EXPECT_TRUE(interval_contains(p.existence.image[0], root));  // ...outside the common part
  // Without the seam: c2 meets a in q ∈ [3.24178, 3.3], again above the solution.
  Box c2 = box(-0.1, 0.1, 3.24178, 3.5);
  ASSERT_TRUE(root < R(3.24178));
  LinkProof p2;
  EXPECT_FALSE(link(a, c2, 0, p2));
}

// Random pairs near the seam. Where the boxes' common part holds no solution (exactly:
// sin is decreasing on (π/2, 3π/2), so the solutions with q ∈ [lo, hi] have x ∈
// [sin hi, sin lo]), no link; a link holds the exact solution at its witness.
TEST_F(Link, RandomPairsAgreeWithTheExactSolutions) {
  std::mt19937 g(14);
  int linked = 0, impossible = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    double xlo = aspects_test::uniform(g, -0.3, 0.3);
    Box a = box(xlo, xlo + aspects_test::uniform(g, 0.01, 0.2), 0, 0);
    double qlo = aspects_test::uniform(g, 2.8, 3.3);
    a[1].set_hull(qlo, qlo + aspects_test::uniform(g, 0.01, 0.3));
    double xlo_b = aspects_test::uniform(g, xlo - 0.1, a[0].hi_up());
    double qlo_b = aspects_test::uniform(g, qlo - 0.3, a[1].hi_up()) - 2 * M_PI;
    Box b = box(xlo_b, xlo_b + aspects_test::uniform(g, 0.01, 0.2), qlo_b,
                qlo_b + aspects_test::uniform(g, 0.01, 0.3));
    // The common part, exactly: x in X = a_x ∩ b_x, q in Q = a_q ∩ (b_q + 2π).
    R x_lo = std::max(R(a[0].lo_down()), R(b[0].lo_down()));
    R x_hi = std::min(R(a[0].hi_up()), R(b[0].hi_up()));
    R q_lo = std::max(R(a[1].lo_down()), R(b[1].lo_down()) + two_pi(1));
    R q_hi = std::min(R(a[1].hi_up()), R(b[1].hi_up()) + two_pi(1));
    if (x_hi < x_lo || q_hi < q_lo) continue;  // not neighbours
    bool shared = !(x_hi < sin(q_hi) || sin(q_lo) < x_lo);
    LinkProof p;
    bool ok = link(a, b, +1, p);
    if (!shared) {
      ++impossible;
      EXPECT_FALSE(ok) << trial;
      continue;
    }
    if (!ok) continue;
    ++linked;
    R root = seam_root(p.witness[0]);
    EXPECT_TRUE(interval_contains(p.existence.image[0], root)) << trial;
    EXPECT_TRUE(q_lo <= root && root <= q_hi) << trial;
  }
  EXPECT_GT(linked, 100);  // not vacuous
  EXPECT_GT(impossible, 100);
}
