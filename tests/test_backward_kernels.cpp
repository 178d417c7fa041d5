// The backward kernels of HC4-Revise (core/model/backward.h), one random containment test
// each (MPFI's type_ii tests turned around): for random boxes [a], [b], a random target
// [r] around the value at a random point, and random points (α, β) of the box, every
// point whose exact value op(α, β) (MPFR at 256 bits, rounded both ways) lies in [r] is
// still in the projected box, and the kernel reports "empty" only when no sampled point
// does. The same kernel on doubles gives the same verdict and the same ends, or declines
// (exp, log, asin, acos, atan, roots): counted, so that the comparison is not vacuous.
//
// Seen failing (each break made in core/model/backward.h, then reverted):
//  - bwd_mul projecting b with r / b instead of r / a: Mul fails;
//  - meet_symmetric keeping only a ∩ p (the negative preimage dropped): Sqr, Pow and Abs
//    fail;
//  - project_periodic without sin's second preimage (π − asin r): Sin fails;
//  - bwd_sub computing b ∩= r − a instead of a − r: Sub fails.
// (Dividing by a b that holds 0 in bwd_mul is no break: MPFI returns the whole line.)
#include <gtest/gtest.h>

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

// The kernel on doubles at the same case: the same verdict and ends as MPFI's, or declined.
// Returns true when it did not decline.
template <class Kernel>
bool same_on_doubles(const Kernel& kernel, const Interval& r, const Interval& a,
                     const Interval& b, Projection mpfi, const Interval& pa, const Interval& pb,
                     BackwardScratch<DInterval>& s) {
  DInterval dr = to_dinterval(r), da = to_dinterval(a), db = to_dinterval(b);
  const Projection p = kernel(dr, da, db, s);
  if (p == Projection::Declined) return false;
  EXPECT_EQ(p, mpfi) << "a=" << interval_str(a) << " b=" << interval_str(b)
                     << " r=" << interval_str(r);
  if (p == Projection::Done && mpfi == Projection::Done) {
    EXPECT_TRUE(da.lo == pa.lo_down() && da.hi == pa.hi_up() && db.lo == pb.lo_down() &&
                db.hi == pb.hi_up())
        << "doubles " << da.lo << " " << da.hi << " MPFI " << interval_str(pa);
  }
  return true;
}

// Runs `trials` random cases of one kernel (a generic lambda, called on MPFI intervals
// and on doubles). Counts how often a point is kept (not vacuous).
template <class Kernel>
void check_kernel(Op op, int k, const Kernel& kernel, const Domain& da, const Domain& db,
                  int trials = 4000, bool contracts = true, bool on_doubles = true) {
  set_working_precision(53);
  aspects_test::ref_prec() = 256;
  BackwardScratch<Interval> s;
  BackwardScratch<DInterval> ds;
  std::mt19937 g(14 + int(op) * 31 + k);
  int kept = 0, contracted = 0, compared = 0;
  for (int t = 0; t < trials; ++t) {
    Interval a = random_interval(g, da), b = random_interval(g, db);
    // [r] around the value at one point of the box, rounded outward, plus a random margin.
    R down, up;
    if (!exact_value(op, k, random_point(g, a), random_point(g, b), down, up)) continue;
    double m = g() % 3 == 0 ? 0 : std::ldexp(uniform(g, 0, 1), -int(g() % 12));
    R lo = down - R(m) * (R(1) + abs(down)), hi = up + R(m) * (R(1) + abs(up));
    Interval r(mpfr_get_d(lo.get(), MPFR_RNDD), mpfr_get_d(hi.get(), MPFR_RNDU));
    Interval pr = r, pa = a, pb = b;
    const Projection p = kernel(pr, pa, pb, s);
    ASSERT_NE(p, Projection::Declined) << "MPFI never declines";
    const bool ok = p == Projection::Done;
    if (same_on_doubles(kernel, r, a, b, p, pa, pb, ds)) ++compared;
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
  if (on_doubles) {
    EXPECT_GT(compared, trials / 2);
  } else {
    EXPECT_EQ(compared, 0);  // doubles decline this kernel
  }
}

const Domain kWide{-8, 8, 6}, kPositive{1e-3, 9, 4}, kUnit{-1, 1, 1.5};

#define BINARY(f) [](auto& r, auto& a, auto& b, auto& s) { return f(r, a, b, s); }
#define UNARY(f) [](auto& r, auto& a, auto&, auto& s) { return f(r, a, s); }

}  // namespace

TEST(BackwardKernel, Add) { check_kernel(Op::Add, 0, BINARY(bwd_add), kWide, kWide); }
TEST(BackwardKernel, Sub) { check_kernel(Op::Sub, 0, BINARY(bwd_sub), kWide, kWide); }
TEST(BackwardKernel, Mul) { check_kernel(Op::Mul, 0, BINARY(bwd_mul), kWide, kWide); }
TEST(BackwardKernel, Div) { check_kernel(Op::Div, 0, BINARY(bwd_div), kWide, kWide); }
TEST(BackwardKernel, Min) { check_kernel(Op::Min, 0, BINARY(bwd_min), kWide, kWide); }
TEST(BackwardKernel, Max) { check_kernel(Op::Max, 0, BINARY(bwd_max), kWide, kWide); }
TEST(BackwardKernel, Neg) { check_kernel(Op::Neg, 0, UNARY(bwd_neg), kWide, kWide); }
TEST(BackwardKernel, Sqr) { check_kernel(Op::Sqr, 0, UNARY(bwd_sqr), kWide, kWide); }

TEST(BackwardKernel, Pow) {
  // The DAG never holds x^0, x^1 or x^2 (Dag::pow makes them 1, x, sqr(x)). Doubles take
  // only k < 0 (a no-op) and decline the k-th roots.
  for (int k : {-3, -2, -1, 3, 4, 5, 6}) {
    auto f = [k](auto& r, auto& a, auto&, auto& s) { return bwd_pow(r, a, k, s); };
    check_kernel(Op::Pow, k, f, Domain{-3, 3, 2}, kWide, 1000, k > 0, k < 0);
  }
}

TEST(BackwardKernel, Sqrt) { check_kernel(Op::Sqrt, 0, UNARY(bwd_sqrt), kWide, kWide); }
TEST(BackwardKernel, Exp) {
  check_kernel(Op::Exp, 0, UNARY(bwd_exp), Domain{-5, 5, 3}, kWide, 1200, true, false);
}
TEST(BackwardKernel, Log) {
  check_kernel(Op::Log, 0, UNARY(bwd_log), kPositive, kWide, 1200, true, false);
}
TEST(BackwardKernel, Abs) { check_kernel(Op::Abs, 0, UNARY(bwd_abs), kWide, kWide); }
TEST(BackwardKernel, Asin) {
  check_kernel(Op::Asin, 0, UNARY(bwd_asin), kUnit, kWide, 1200, true, false);
}
TEST(BackwardKernel, Acos) {
  check_kernel(Op::Acos, 0, UNARY(bwd_acos), kUnit, kWide, 1200, true, false);
}
TEST(BackwardKernel, Atan) {
  check_kernel(Op::Atan, 0, UNARY(bwd_atan), kWide, kWide, 1200, true, false);
}

// sin and cos over several periods: every preimage branch, shifted by 2kπ, is kept.
TEST(BackwardKernel, Sin) {
  check_kernel(Op::Sin, 0, UNARY(bwd_sin), Domain{-20, 20, 8}, kWide);
}
TEST(BackwardKernel, Cos) {
  check_kernel(Op::Cos, 0, UNARY(bwd_cos), Domain{-20, 20, 8}, kWide);
}
