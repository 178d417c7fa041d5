// The backward kernels of HC4-Revise (core/model/backward.*), one random containment test each
// (MPFI's type_ii tests turned around): for random boxes [a], [b], a random target [r]
// around the value at a random point, and random points (α, β) of the box, every point
// whose exact value op(α, β) (MPFR at 256 bits, rounded both ways) lies in [r] is still
// in the projected box, and the kernel reports "empty" only when no sampled point does.
//
// Seen failing (each break made in core/model/backward.cpp, then reverted):
//  - bwd_mul projecting b with r / b instead of r / a: Mul fails;
//  - meet_symmetric keeping only a ∩ p (the negative preimage dropped): Sqr, Pow and Abs
//    fail;
//  - project_periodic without sin's second preimage (π − asin r): Sin fails;
//  - bwd_sub computing b ∩= r − a instead of a − r: Sub fails.
// (Dividing by a b that holds 0 in bwd_mul is no break: MPFI returns the whole line.)
#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <string>

#include "model/backward.h"
#include "model/expr.h"
#include "test_util.h"

using namespace aspects;
using aspects_test::interval_contains;
using aspects_test::interval_str;
using aspects_test::R;
using aspects_test::uniform;

namespace {

using Kernel = std::function<bool(Interval& r, Interval& a, Interval& b, BackwardScratch& s)>;

struct Domain {
  double lo, hi;  // where a's (and b's) endpoints are drawn
  double max_width;
};

// [lo, hi] with double endpoints, inside the domain (sometimes a single point).
Interval random_interval(std::mt19937& g, const Domain& d) {
  double lo = uniform(g, d.lo, d.hi);
  double w = g() % 8 == 0 ? 0 : uniform(g, 0, d.max_width);
  double hi = std::min(d.hi, lo + w);
  return Interval(lo, hi);
}

double random_point(std::mt19937& g, const Interval& x) {
  switch (g() % 6) {
    case 0: return x.lo_down();  // the ends too
    case 1: return x.hi_up();
    default: return uniform(g, x.lo_down(), x.hi_up());
  }
}

// The exact value of op at (α, β), as [down, up] (equal unless rounded); false where
// undefined.
bool exact_value(Op op, int k, double alpha, double beta, R& down, R& up) {
  R a(alpha), b(beta);
  if (!aspects_test::exact_op(op, k, down.get(), a.get(), b.get(), MPFR_RNDD)) return false;
  aspects_test::exact_op(op, k, up.get(), a.get(), b.get(), MPFR_RNDU);
  return true;
}

// Runs `trials` random cases of one kernel. Counts how often a point is kept (not vacuous).
void check_kernel(Op op, int k, const Kernel& kernel, const Domain& da, const Domain& db,
                  int trials = 4000, bool contracts = true) {
  set_working_precision(53);
  aspects_test::ref_prec() = 256;
  BackwardScratch s;
  std::mt19937 g(14 + int(op) * 31 + k);
  int kept = 0, contracted = 0;
  for (int t = 0; t < trials; ++t) {
    Interval a = random_interval(g, da), b = random_interval(g, db);
    // [r] around the value at one point of the box, rounded outward, plus a random margin.
    R down, up;
    if (!exact_value(op, k, random_point(g, a), random_point(g, b), down, up)) continue;
    double m = g() % 3 == 0 ? 0 : std::ldexp(uniform(g, 0, 1), -int(g() % 12));
    R lo = down - R(m) * (R(1) + abs(down)), hi = up + R(m) * (R(1) + abs(up));
    Interval r(mpfr_get_d(lo.get(), MPFR_RNDD), mpfr_get_d(hi.get(), MPFR_RNDU));
    Interval pr = r, pa = a, pb = b;
    bool ok = kernel(pr, pa, pb, s);
    if (ok && (!a.contains(pa) || !b.contains(pb))) ADD_FAILURE() << "the kernel widened";
    if (ok && (pa.width_up() < a.width_up() || pb.width_up() < b.width_up())) ++contracted;
    for (int i = 0; i < 20; ++i) {
      double alpha = random_point(g, a), beta = random_point(g, b);
      if (!exact_value(op, k, alpha, beta, down, up)) continue;
      bool satisfies = interval_contains(r, down) && interval_contains(r, up);
      if (!satisfies) continue;
      ++kept;
      ASSERT_TRUE(ok) << "emptied a box holding a solution: a=" << interval_str(a)
                      << " b=" << interval_str(b) << " r=" << interval_str(r);
      ASSERT_TRUE(pa.contains(alpha) && pb.contains(beta))
          << "removed (" << alpha << ", " << beta << ") value " << down.str()
          << ": a=" << interval_str(a) << " -> " << interval_str(pa) << ", b=" << interval_str(b)
          << " -> " << interval_str(pb) << ", r=" << interval_str(r);
    }
  }
  EXPECT_GT(kept, trials);  // not vacuous
  if (contracts) {
    EXPECT_GT(contracted, trials / 20);
  }
}

const Domain kWide{-8, 8, 6}, kPositive{1e-3, 9, 4}, kUnit{-1, 1, 1.5};

Kernel unary(std::function<bool(Interval&, Interval&, BackwardScratch&)> f) {
  return [f](Interval& r, Interval& a, Interval&, BackwardScratch& s) { return f(r, a, s); };
}

}  // namespace

TEST(BackwardKernel, Add) { check_kernel(Op::Add, 0, bwd_add, kWide, kWide); }
TEST(BackwardKernel, Sub) { check_kernel(Op::Sub, 0, bwd_sub, kWide, kWide); }
TEST(BackwardKernel, Mul) { check_kernel(Op::Mul, 0, bwd_mul, kWide, kWide); }
TEST(BackwardKernel, Div) { check_kernel(Op::Div, 0, bwd_div, kWide, kWide); }
TEST(BackwardKernel, Min) { check_kernel(Op::Min, 0, bwd_min, kWide, kWide); }
TEST(BackwardKernel, Max) { check_kernel(Op::Max, 0, bwd_max, kWide, kWide); }
TEST(BackwardKernel, Neg) { check_kernel(Op::Neg, 0, unary(bwd_neg), kWide, kWide); }
TEST(BackwardKernel, Sqr) { check_kernel(Op::Sqr, 0, unary(bwd_sqr), kWide, kWide); }

TEST(BackwardKernel, Pow) {
  // The DAG never holds x^0, x^1 or x^2 (Dag::pow makes them 1, x, sqr(x)).
  for (int k : {-3, -2, -1, 3, 4, 5, 6}) {
    auto f = [k](Interval& r, Interval& a, Interval&, BackwardScratch& s) {
      return bwd_pow(r, a, k, s);
    };
    check_kernel(Op::Pow, k, f, Domain{-3, 3, 2}, kWide, 1000, k > 0);  // k < 0: no-op
  }
}

TEST(BackwardKernel, Sqrt) { check_kernel(Op::Sqrt, 0, unary(bwd_sqrt), kWide, kWide); }
TEST(BackwardKernel, Exp) {
  check_kernel(Op::Exp, 0, unary(bwd_exp), Domain{-5, 5, 3}, kWide, 1200);
}
TEST(BackwardKernel, Log) { check_kernel(Op::Log, 0, unary(bwd_log), kPositive, kWide, 1200); }
TEST(BackwardKernel, Abs) { check_kernel(Op::Abs, 0, unary(bwd_abs), kWide, kWide); }
TEST(BackwardKernel, Asin) { check_kernel(Op::Asin, 0, unary(bwd_asin), kUnit, kWide, 1200); }
TEST(BackwardKernel, Acos) { check_kernel(Op::Acos, 0, unary(bwd_acos), kUnit, kWide, 1200); }
TEST(BackwardKernel, Atan) { check_kernel(Op::Atan, 0, unary(bwd_atan), kWide, kWide, 1200); }

// sin and cos over several periods: every preimage branch, shifted by 2kπ, is kept.
TEST(BackwardKernel, Sin) {
  Interval two_pi;
  mpfi_const_pi(two_pi.get());
  mpfi_mul_2ui(two_pi.get(), two_pi.get(), 1);
  auto f = [&](Interval& r, Interval& a, Interval&, BackwardScratch& s) {
    return bwd_sin(r, a, two_pi, s);
  };
  check_kernel(Op::Sin, 0, f, Domain{-20, 20, 8}, kWide);
}

TEST(BackwardKernel, Cos) {
  Interval two_pi;
  mpfi_const_pi(two_pi.get());
  mpfi_mul_2ui(two_pi.get(), two_pi.get(), 1);
  auto f = [&](Interval& r, Interval& a, Interval&, BackwardScratch& s) {
    return bwd_cos(r, a, two_pi, s);
  };
  check_kernel(Op::Cos, 0, f, Domain{-20, 20, 8}, kWide);
}
