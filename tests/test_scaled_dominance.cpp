// P2's regularity test with column weights (proofs/strong_regularity.*): C·[A]·diag(D)
// strictly diagonally dominant. Ground truth is exact: 2×2 determinants of the vertex
// matrices (det is affine in each entry, so its range over an interval matrix is
// attained at vertices), computed in long double on small dyadic inputs, where it is
// exact. Broken on purpose to see these fail: with the diagonal left unweighted in
// dominant(), WeightsProveWhatRowSumsCannot fails; comparing the right end of the
// diagonal with the left end of the off-diagonal sum fails it, SingularMemberIsNeverProved
// and RandomSingularMembers.
#include <gtest/gtest.h>

#include <random>

#include "strong_regularity.h"

using namespace aspects;

namespace {

IMatrix make(double a_lo, double a_hi, double b_lo, double b_hi, double c_lo, double c_hi,
             double d_lo, double d_hi) {
  IMatrix A(2, 2);
  A(0, 0) = Interval(a_lo, a_hi);
  A(0, 1) = Interval(b_lo, b_hi);
  A(1, 0) = Interval(c_lo, c_hi);
  A(1, 1) = Interval(d_lo, d_hi);
  return A;
}

// True when some vertex matrix of the 2×2 interval matrix is singular or two vertices
// have determinants of opposite signs: then [A] holds a singular matrix.
bool holds_singular(const IMatrix& A) {
  int pos = 0, neg = 0;
  for (int m = 0; m < 16; ++m) {
    long double e[4];
    for (int k = 0; k < 4; ++k) {
      const Interval& x = A(k / 2, k % 2);
      e[k] = (m >> k) & 1 ? x.hi_up() : x.lo_down();
    }
    long double det = e[0] * e[3] - e[1] * e[2];
    if (det > 0) ++pos;
    else if (det < 0) ++neg;
    else return true;
  }
  return pos && neg;
}

}  // namespace

TEST(ScaledDominance, WeightsProveWhatRowSumsCannot) {
  // Row 0 of C·A = A (C = I) has off-diagonal magnitude 1.5 > 1: the paper's test fails.
  // ρ(G) = sqrt(1.5 · 0.125) < 1, and det ≥ 1 − 1.5·0.125 > 0 on the whole matrix.
  IMatrix A = make(1, 1, -1.5, 1.5, -0.125, 0.125, 1, 1);
  std::vector<double> C, D;
  ASSERT_FALSE(diagonally_dominant_after({1, 0, 0, 1}, A, {1, 1}));
  ASSERT_TRUE(strongly_regular(A, &C, &D));
  ASSERT_EQ(D.size(), 2u);
  EXPECT_GT(D[0], 1.5 * D[1]);  // row 0's diagonal outweighs its wide entry
  EXPECT_TRUE(diagonally_dominant_after(C, A, D));
  EXPECT_FALSE(holds_singular(A));
}

TEST(ScaledDominance, UnscaledSuccessKeepsUnitWeights) {
  IMatrix A = make(4, 4.5, -1, 1, -1, 1, 4, 4.5);
  std::vector<double> C, D;
  ASSERT_TRUE(strongly_regular(A, &C, &D));
  EXPECT_EQ(D, (std::vector<double>{1, 1}));
}

TEST(ScaledDominance, SingularMemberIsNeverProved) {
  // [[1, 2], [0.5, 1]] is a member (det 0): ρ(G) = 1 exactly.
  IMatrix A = make(1, 1, -2, 2, -0.5, 0.5, 1, 1);
  ASSERT_TRUE(holds_singular(A));
  EXPECT_FALSE(strongly_regular(A));
  // Slightly beyond: ρ(G) > 1.
  EXPECT_FALSE(strongly_regular(make(1, 1, -2.25, 2.25, -0.5, 0.5, 1, 1)));
}

TEST(ScaledDominance, RandomSingularMembers) {
  // Random interval matrices around a singular point matrix (dyadic, so exact): never
  // proved, whatever the scales of the columns. And random ones proved regular really
  // are (checked on every vertex).
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> small(-64, 64), rad(0, 16);
  int proved = 0;
  for (int t = 0; t < 20000; ++t) {
    double col_scale = std::ldexp(1.0, int(rng() % 12) - 6);
    double a = small(rng) / 8.0, b = small(rng) / 8.0 * col_scale, c = small(rng) / 8.0;
    double d = small(rng) / 8.0 * col_scale;
    if (t % 2 == 0) {  // a·d − b·c = 0 exactly: small dyadic products are exact doubles
      c = 1;
      d = a * b;
    }
    double r[4];
    for (double& x : r) x = rad(rng) / 64.0;
    r[1] *= col_scale;
    r[3] *= col_scale;
    IMatrix A = make(a - r[0], a + r[0], b - r[1], b + r[1], c - r[2], c + r[2], d - r[3],
                     d + r[3]);
    bool singular = holds_singular(A);
    std::vector<double> C, D;
    bool ok = strongly_regular(A, &C, &D);
    if (ok) ++proved;
    ASSERT_FALSE(ok && singular) << "t=" << t << " a=" << a << " b=" << b << " c=" << c
                                 << " d=" << d;
  }
  EXPECT_GT(proved, 1000);  // the test is not vacuous
}
