// P2 alone (proofs/strong_regularity.*): an interval matrix holding a singular matrix is
// never proved regular, whatever the preconditioner C (the approximate inverse of the
// midpoint, random matrices, inverses of nearby matrices, the identity). The singular
// members are integer matrices whose determinant is computed exactly (GMP rationals);
// nonsingular ones with thin radii are proved, so the test is not vacuous.
//
// Seen failing (each break made in proofs/strong_regularity.cpp, then reverted):
//  - the dominance test compares the right end of |diag| (its magnitude) instead of the
//    left end (its mignitude) with the off-diagonal sum:
//    SingularMemberOfRandomMatricesIsNeverProved fails;
//  - the off-diagonal sum skips column 0 (`if (j == 0 && i != j) continue;`):
//    SingularMemberAtACornerIsNeverProved and SingularMemberOfRandomMatricesIsNeverProved
//    fail.
//
// With column weights (C·[A]·diag(D) strictly diagonally dominant, D > 0), the
// ScaledDominance tests. Ground truth is exact: 2×2 determinants of the vertex matrices
// (det is affine in each entry, so its range over an interval matrix is attained at
// vertices), computed in long double on small dyadic inputs, where it is exact. Seen
// failing: with the diagonal left unweighted in dominant(), WeightsProveWhatRowSumsCannot;
// comparing the right end of the diagonal with the left end of the off-diagonal sum,
// it, SingularMemberIsNeverProved and RandomSingularMembers.
#include <gmp.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "strong_regularity.h"

using namespace aspects;

namespace {

// Exact determinant of an integer matrix (Gaussian elimination over the rationals).
bool exactly_singular(const std::vector<std::vector<long>>& S) {
  const size_t n = S.size();
  std::vector<mpq_t> a(n * n);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) {
      mpq_init(a[i * n + j]);
      mpq_set_si(a[i * n + j], S[i][j], 1);
    }
  mpq_t f, t;
  mpq_init(f);
  mpq_init(t);
  bool singular = false;
  for (size_t c = 0; c < n && !singular; ++c) {
    size_t p = c;
    while (p < n && mpq_sgn(a[p * n + c]) == 0) ++p;
    if (p == n) {
      singular = true;
      break;
    }
    for (size_t j = 0; j < n; ++j) mpq_swap(a[p * n + j], a[c * n + j]);
    for (size_t i = c + 1; i < n; ++i) {
      mpq_div(f, a[i * n + c], a[c * n + c]);
      for (size_t j = c; j < n; ++j) {
        mpq_mul(t, f, a[c * n + j]);
        mpq_sub(a[i * n + j], a[i * n + j], t);
      }
    }
  }
  mpq_clear(f);
  mpq_clear(t);
  for (auto& x : a) mpq_clear(x);
  return singular;
}

// [A] = S + [-rlo, rhi] entrywise, with double endpoints: S itself is a member.
IMatrix around(const std::vector<std::vector<long>>& S, std::mt19937& g, double rmax) {
  int n = int(S.size());
  IMatrix A(n, n);
  std::uniform_real_distribution<double> r(0, rmax);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) A(i, j).set_hull(double(S[i][j]) - r(g), double(S[i][j]) + r(g));
  return A;
}

// An integer n×n matrix of rank < n: the last row is an integer combination of the others.
std::vector<std::vector<long>> random_singular(int n, std::mt19937& g) {
  std::uniform_int_distribution<long> e(-9, 9), w(-3, 3);
  std::vector<std::vector<long>> S(n, std::vector<long>(n, 0));
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j < n; ++j) S[i][j] = e(g);
  for (int i = 0; i + 1 < n; ++i) {
    long c = w(g);
    for (int j = 0; j < n; ++j) S[n - 1][j] += c * S[i][j];
  }
  std::shuffle(S.begin(), S.end(), g);  // the dependent row anywhere
  return S;
}

// Preconditioners to try on [A]: its own choice, the identity, random matrices, and the
// approximate inverses of random matrices near mid([A]).
std::vector<std::vector<double>> preconditioners(const IMatrix& A, std::mt19937& g) {
  int n = A.rows();
  std::vector<std::vector<double>> Cs;
  std::vector<double> C;
  if (approximate_inverse(A, C)) Cs.push_back(C);
  std::vector<double> I(size_t(n) * n, 0.0);
  for (int i = 0; i < n; ++i) I[size_t(i) * n + i] = 1;
  Cs.push_back(I);
  std::normal_distribution<double> N(0, 1);
  for (int k = 0; k < 20; ++k) {
    std::vector<double> R(size_t(n) * n);
    for (double& x : R) x = N(g);
    Cs.push_back(R);
    IMatrix P(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) P(i, j).set_point(A(i, j).mid() + 1e-3 * N(g));
    if (approximate_inverse(P, C)) Cs.push_back(C);
  }
  return Cs;
}

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

TEST(StrongRegularity, SingularMemberAtTheMidpointIsNeverProved) {
  set_working_precision(53);
  std::mt19937 g(2);
  std::vector<std::vector<long>> S = {{1, 2}, {2, 4}};
  ASSERT_TRUE(exactly_singular(S));
  for (double r : {0.0, 1e-12, 1e-3, 0.5}) {
    IMatrix A = around(S, g, r);
    EXPECT_FALSE(strongly_regular(A)) << r;
    for (const auto& C : preconditioners(A, g)) EXPECT_FALSE(diagonally_dominant_after(C, A));
  }
}

TEST(StrongRegularity, SingularMemberAtACornerIsNeverProved) {
  set_working_precision(53);
  std::mt19937 g(3);
  // [A] = S + [0, r]: S is the lower corner, mid([A]) is nonsingular.
  std::vector<std::vector<long>> S = {{2, 1, 0}, {1, 2, 1}, {3, 3, 1}};
  ASSERT_TRUE(exactly_singular(S));
  for (double r : {1e-9, 1e-4, 0.1}) {
    IMatrix A(3, 3);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) A(i, j).set_hull(double(S[i][j]), double(S[i][j]) + r);
    EXPECT_FALSE(strongly_regular(A)) << r;
    for (const auto& C : preconditioners(A, g)) EXPECT_FALSE(diagonally_dominant_after(C, A));
  }
}

TEST(StrongRegularity, SingularMemberOfRandomMatricesIsNeverProved) {
  set_working_precision(53);
  std::mt19937 g(14);
  for (int trial = 0; trial < 300; ++trial) {
    int n = 2 + trial % 4;
    auto S = random_singular(n, g);
    ASSERT_TRUE(exactly_singular(S));
    const double radii[] = {0.0, 1e-10, 1e-2};
    double rmax = radii[trial % 3];
    IMatrix A = around(S, g, rmax);
    EXPECT_FALSE(strongly_regular(A)) << trial;
    for (const auto& C : preconditioners(A, g))
      EXPECT_FALSE(diagonally_dominant_after(C, A)) << trial;
  }
}

// Not vacuous: thin enclosures of nonsingular integer matrices are proved regular.
TEST(StrongRegularity, ThinNonsingularMatricesAreProved) {
  set_working_precision(53);
  std::mt19937 g(15);
  std::uniform_int_distribution<long> e(-9, 9);
  int proved = 0, tried = 0;
  for (int trial = 0; trial < 300; ++trial) {
    int n = 2 + trial % 4;
    std::vector<std::vector<long>> S(n, std::vector<long>(n));
    for (auto& row : S)
      for (long& x : row) x = e(g);
    if (exactly_singular(S)) continue;
    ++tried;
    std::vector<double> C;
    if (strongly_regular(around(S, g, 1e-9), &C)) ++proved;
  }
  EXPECT_GT(proved, tried * 9 / 10);
}

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
