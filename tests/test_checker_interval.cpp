// test_checker_interval.cpp — check_cert's intervals of doubles (certificates/checker/
// interval.cpp) against MPFI at 53 bits: end for end on random operands whose results are
// doubles, enclosure where they leave the range of doubles; and the ends of sin, cos and
// the inverse branches (Arb's balls in eval.cpp) at most one ulp wide around MPFR's
// correctly rounded values. Deliberate breaks that made it fail: `down` not stepping below
// a sum whose TwoSum error is negative (MatchMpfiEndForEnd: 1 of the ops, thousands of
// cases); the check of the underflow threshold of products removed (EncloseMpfiNearTheLimits);
// Arb's balls no longer retried while two ulps wide (TrigEndsAreOneUlpAroundMpfr, at
// sin 2^-40 and cos near 1); the memo of ends giving back the cosine as the sine (the same
// test, on its second pass).
#include <gtest/gtest.h>
#include <mpfr.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "../certificates/checker/checker.h"

namespace {

using cc::Ival;

struct Mpfi {
  mpfi_t v;
  Mpfi() { mpfi_init2(v, 53); }
  ~Mpfi() { mpfi_clear(v); }
};

class CheckerInterval : public ::testing::Test {
 protected:
  void SetUp() override { cc::set_interval_precision(53, true); }
  void TearDown() override { cc::set_interval_precision(53, false); }
};

// A double with a random sign, 53 random bits and an exponent in [-e, e]; sometimes 0.
double random_double(std::mt19937_64& rng, int e) {
  std::uniform_int_distribution<int> ex(-e, e), coin(0, 15);
  if (coin(rng) == 0) return 0.0;
  const double m = 1.0 + double(rng() >> 11) * 0x1p-53;
  return (coin(rng) & 1 ? -1 : 1) * std::ldexp(m, ex(rng));
}

void random_interval(std::mt19937_64& rng, int e, Ival& x, Mpfi& y) {
  double a = random_double(rng, e), b = random_double(rng, e);
  if (rng() % 8 == 0) b = a;  // a point
  if (b < a) std::swap(a, b);
  x.set(a, b);
  mpfi_interv_d(y.v, a, b);
}

// r encloses the MPFI result, and equals it wherever MPFI's ends are doubles.
void expect_match(const Ival& r, const Mpfi& m, const char* op, double a, double b) {
  const double lo = mpfr_get_d(&m.v->left, MPFR_RNDD), hi = mpfr_get_d(&m.v->right, MPFR_RNDU);
  const bool exact_lo = mpfr_cmp_d(&m.v->left, lo) == 0, exact_hi = mpfr_cmp_d(&m.v->right, hi) == 0;
  if (exact_lo) {
    EXPECT_EQ(r.lo(), lo) << op << " lo, operands " << a << " " << b;
  }
  if (exact_hi) {
    EXPECT_EQ(r.hi(), hi) << op << " hi, operands " << a << " " << b;
  }
  EXPECT_GE(mpfr_cmp_d(&m.v->left, r.lo()), 0) << op << " lo does not enclose";
  EXPECT_LE(mpfr_cmp_d(&m.v->right, r.hi()), 0) << op << " hi does not enclose";
}

using Binary = std::function<void(Ival&, const Ival&, const Ival&)>;
using MpfiBinary = std::function<void(mpfi_ptr, mpfi_srcptr, mpfi_srcptr)>;

void compare_binary(const char* name, Binary ours, MpfiBinary theirs, int e, bool nonzero_b,
                    int cases) {
  std::mt19937_64 rng(12345);
  for (int i = 0; i < cases; ++i) {
    Ival a, b, r;
    Mpfi A, B, R;
    random_interval(rng, e, a, A);
    random_interval(rng, e, b, B);
    if (nonzero_b && b.has_zero()) continue;
    ours(r, a, b);
    theirs(R.v, A.v, B.v);
    expect_match(r, R, name, a.lo(), b.lo());
    if (::testing::Test::HasFailure()) return;
  }
}

TEST_F(CheckerInterval, MatchMpfiEndForEnd) {
  const int n = 20000;
  compare_binary("add", cc::add, mpfi_add, 60, false, n);
  compare_binary("sub", cc::sub, mpfi_sub, 60, false, n);
  compare_binary("mul", cc::mul, mpfi_mul, 60, false, n);
  compare_binary("div", cc::div, mpfi_div, 60, true, n);
  compare_binary("hull", cc::hull, mpfi_union, 60, false, n);
  compare_binary("add, far exponents", cc::add, mpfi_add, 400, false, n);
  compare_binary("mul, far exponents", cc::mul, mpfi_mul, 400, false, n);
  compare_binary("div, far exponents", cc::div, mpfi_div, 400, true, n);
  std::mt19937_64 rng(7);
  for (int i = 0; i < n; ++i) {
    Ival a, r;
    Mpfi A, R;
    random_interval(rng, 300, a, A);
    cc::sqr(r, a);
    mpfi_sqr(R.v, A.v);
    expect_match(r, R, "sqr", a.lo(), a.hi());
    cc::neg(r, a);
    mpfi_neg(R.v, A.v);
    expect_match(r, R, "neg", a.lo(), a.hi());
    cc::abs(r, a);
    mpfi_abs(R.v, A.v);
    expect_match(r, R, "abs", a.lo(), a.hi());
    const double d = random_double(rng, 30);
    cc::mul_d(r, a, d);
    mpfi_mul_d(R.v, A.v, d);
    expect_match(r, R, "mul_d", a.lo(), d);
    cc::add_d(r, a, d);
    mpfi_add_d(R.v, A.v, d);
    expect_match(r, R, "add_d", a.lo(), d);
    if (!a.has_zero()) {
      cc::inv(r, a);
      mpfi_inv(R.v, A.v);
      expect_match(r, R, "inv", a.lo(), a.hi());
    }
    cc::abs(a, a);
    mpfi_abs(A.v, A.v);
    cc::sqrt(r, a);
    mpfi_sqrt(R.v, A.v);
    expect_match(r, R, "sqrt", a.lo(), a.hi());
    if (HasFailure()) return;
  }
}

// Results below the underflow threshold or beyond the largest double: MPFI's (wider exponent
// range) values are enclosed, rounded outward.
TEST_F(CheckerInterval, EncloseMpfiNearTheLimits) {
  compare_binary("mul near the limits", cc::mul, mpfi_mul, 1023, false, 20000);
  compare_binary("div near the limits", cc::div, mpfi_div, 1023, true, 20000);
  compare_binary("add near the limits", cc::add, mpfi_add, 1023, false, 20000);
  Ival a, r;
  a.set(0x1p-600, 0x1.8p-540);
  cc::sqr(r, a);  // 2^-1200 is no double: [0, 2^-1074] at least
  EXPECT_EQ(r.lo(), 0.0);
  EXPECT_GT(r.hi(), 0.0);
  a.entire();
  Ival b;
  b.set(1, 2);
  cc::add(r, a, b);
  EXPECT_EQ(r.lo(), -INFINITY);
  EXPECT_EQ(r.hi(), INFINITY);
}

// sin(q) = x, evaluated on point boxes and contracted by HC4; cos(q) (the derivative).
cc::Model trig_model() {
  return cc::parse_model(
      "robot T\npose x in [-100, 100]\ncommand q in [-100, 100]\n"
      "equation sin(q) - x = 0\n");
}

int node_of(const cc::Model& m, cc::Op op) {
  for (size_t i = 0; i < m.nodes.size(); ++i)
    if (m.nodes[i].op == op) return int(i);
  return -1;
}

// The value is one or two doubles around f(t) correctly rounded, never wider.
void expect_tight(const Ival& v, double t, int (*f)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t),
                  const char* name) {
  mpfr_t x, lo, hi;
  mpfr_inits2(53, x, lo, hi, (mpfr_ptr)nullptr);
  mpfr_set_d(x, t, MPFR_RNDN);
  f(lo, x, MPFR_RNDD);
  f(hi, x, MPFR_RNDU);
  EXPECT_EQ(v.lo(), mpfr_get_d(lo, MPFR_RNDD)) << name << "(" << t << ") lo";
  EXPECT_EQ(v.hi(), mpfr_get_d(hi, MPFR_RNDU)) << name << "(" << t << ") hi";
  mpfr_clears(x, lo, hi, (mpfr_ptr)nullptr);
}

void trig_ends_are_mpfrs() {
  const cc::Model m = trig_model();
  cc::Evaluator ev(m);
  const int s = node_of(m, cc::Op::Sin);
  ASSERT_GE(s, 0);
  std::vector<double> points = {0x1p-40, -0x1.3a0801026abffp-36, 0x1.0044f6b60b7ap-16, 1e-30,
                                3.141592653589793, -6.283185307179586, 1.5707963267948966,
                                0.0, 1.0, -2.5};
  std::mt19937_64 rng(3);
  for (int i = 0; i < 2000; ++i) points.push_back(random_double(rng, 6));
  std::vector<Ival> box(2);
  for (int pass = 0; pass < 2; ++pass)  // the second pass finds most ends in the memo
  for (double t : points) {
    if (!(std::fabs(t) < 100)) continue;
    box[0].set(0, 0);
    box[1].set(t, t);
    ASSERT_TRUE(ev.eval_ad(ev.all_eqs, box.data(), 2));
    expect_tight(ev.val(s), t, mpfr_sin, "sin");
    expect_tight(ev.der(s, 1), t, mpfr_cos, "cos");
    if (::testing::Test::HasFailure()) return;
  }
}

// HC4 on sin(q) = x with q on one branch: q shrinks to the branch inverse of x, asin(x)
// rounded outward, one ulp wide at most.
void branch_inverse_is_tight() {
  const cc::Model m = trig_model();
  cc::Evaluator ev(m);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-0.98, 0.98);
  for (int i = 0; i < 500; ++i) {
    const double x = u(rng);
    std::vector<Ival> box(2);
    box[0].set(x, x);
    box[1].set(-1.4, 1.4);  // inside the branch [-pi/2, pi/2]
    ASSERT_TRUE(ev.hc4(0, box.data()));
    expect_tight(box[1], x, mpfr_asin, "asin");
    if (::testing::Test::HasFailure()) return;
  }
}

// The speed layer's trigonometry (Arb's balls at the ends, on doubles) and the trusted
// core's (MPFI, --trusted-only) give the same ends: MPFR's, correctly rounded.
TEST_F(CheckerInterval, TrigEndsAreOneUlpAroundMpfr) { trig_ends_are_mpfrs(); }
TEST_F(CheckerInterval, BranchInverseIsTight) { branch_inverse_is_tight(); }

TEST_F(CheckerInterval, TrustedTrigEndsAreMpfrs) {
  cc::set_interval_precision(53, false);
  cc::Evaluator::speed = false;
  trig_ends_are_mpfrs();
  branch_inverse_is_tight();
  cc::Evaluator::speed = true;
}

}  // namespace
