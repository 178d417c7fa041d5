// SinCos (core/numerics/sincos.*): the joint enclosure of sin and cos over an interval.
// Ground truth: the range of sin and cos over [lo, hi] computed independently with MPFR
// at 256 bits — the endpoint values and, for every multiple of π/2 inside, the extreme
// value ±1 reached there. The enclosure must contain that range; in the one-quadrant
// fast path it must also be tight (within a few ulps of it).
// At 53 bits the endpoint values come from Arb, above from MPFR (HigherPrecisionStaysSound).
// Break it to see it fail: swap `sin_up` for `!sin_up` in sincos.cpp (both random
// tests fail), or exchange two critical values across quadrants (AcrossQuadrantsIsTight
// and RandomIntervalsContainTheExactRange fail), or round Arb's ball outward the wrong way in ArbBounds::Balls::bounds (FLOOR
// and CEIL exchanged: the containment tests fail). The 1e-9 margin of the quadrant test
// cannot be caught this way: an extremum within rounding of an endpoint changes the range
// by far less than the one-ulp outward step; the margin is there by the error bound
// stated in sincos.cpp.
#include <gtest/gtest.h>

#include <mpfr.h>

#include <cmath>
#include <random>

#include "numerics/interval.h"
#include "numerics/sincos.h"

using namespace aspects;

namespace {

struct Range {
  double s_lo, s_hi, c_lo, c_hi;  // exact range rounded outward to doubles
};

// Range of sin and cos over [lo, hi] (width < 2π), from MPFR at 256 bits.
Range exact_range(double lo, double hi) {
  mpfr_t t, s, c, half_pi, k_pi;
  mpfr_inits2(256, t, s, c, half_pi, k_pi, static_cast<mpfr_ptr>(nullptr));
  mpfr_const_pi(half_pi, MPFR_RNDN);
  mpfr_div_2ui(half_pi, half_pi, 1, MPFR_RNDN);
  Range r{INFINITY, -INFINITY, INFINITY, -INFINITY};
  auto take = [&](mpfr_srcptr x) {
    mpfr_sin_cos(s, c, x, MPFR_RNDN);
    r.s_lo = std::min(r.s_lo, mpfr_get_d(s, MPFR_RNDD));
    r.s_hi = std::max(r.s_hi, mpfr_get_d(s, MPFR_RNDU));
    r.c_lo = std::min(r.c_lo, mpfr_get_d(c, MPFR_RNDD));
    r.c_hi = std::max(r.c_hi, mpfr_get_d(c, MPFR_RNDU));
  };
  mpfr_set_d(t, lo, MPFR_RNDN);
  take(t);
  mpfr_set_d(t, hi, MPFR_RNDN);
  take(t);
  // Multiples of π/2 in [lo, hi]: extreme points of sin or cos (value exactly 0 or ±1).
  long k0 = long(std::floor(lo / M_PI_2)) - 1, k1 = long(std::ceil(hi / M_PI_2)) + 1;
  for (long k = k0; k <= k1; ++k) {
    mpfr_mul_si(k_pi, half_pi, k, MPFR_RNDN);
    if (mpfr_cmp_d(k_pi, lo) < 0 || mpfr_cmp_d(k_pi, hi) > 0) continue;
    long m = ((k % 4) + 4) % 4;  // sin, cos at kπ/2 = (0,1), (1,0), (0,-1), (-1,0)
    double sv = m == 1 ? 1 : m == 3 ? -1 : 0, cv = m == 0 ? 1 : m == 2 ? -1 : 0;
    r.s_lo = std::min(r.s_lo, sv);
    r.s_hi = std::max(r.s_hi, sv);
    r.c_lo = std::min(r.c_lo, cv);
    r.c_hi = std::max(r.c_hi, cv);
  }
  mpfr_clears(t, s, c, half_pi, k_pi, static_cast<mpfr_ptr>(nullptr));
  return r;
}

void check(double lo, double hi, bool expect_tight) {
  SinCos sc;
  Interval a(lo, hi), s, c;
  sc.enclose(a, s, c);
  Range r = exact_range(lo, hi);
  SCOPED_TRACE(::testing::Message() << std::hexfloat << "[" << lo << ", " << hi << "]");
  ASSERT_LE(s.lo_down(), r.s_lo);
  ASSERT_GE(s.hi_up(), r.s_hi);
  ASSERT_LE(c.lo_down(), r.c_lo);
  ASSERT_GE(c.hi_up(), r.c_hi);
  if (!expect_tight) return;
  // A few ulps of slack: one for the outward step, one for the double rounding here.
  double u = 4 * std::ldexp(1.0, -52);
  EXPECT_GE(s.lo_down(), r.s_lo - u);
  EXPECT_LE(s.hi_up(), r.s_hi + u);
  EXPECT_GE(c.lo_down(), r.c_lo - u);
  EXPECT_LE(c.hi_up(), r.c_hi + u);
}

TEST(SinCos, RandomIntervalsContainTheExactRange) {
  set_working_precision(53);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> centre(-60, 60), logw(-20, 1.2);
  for (int i = 0; i < 20000; ++i) {
    double lo = centre(rng), w = i % 10 == 0 ? 0 : std::pow(10.0, logw(rng));
    check(lo, lo + w, false);
  }
}

TEST(SinCos, InsideOneQuadrantIsTight) {
  set_working_precision(53);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> quadrant(-40, 40), frac(0.01, 0.98), w(0, 0.01);
  for (int i = 0; i < 5000; ++i) {
    double lo = (std::floor(quadrant(rng)) + frac(rng)) * M_PI_2;
    check(lo, lo + w(rng), true);
  }
}

// Ends in different quadrants, each safely inside its own: the range is the ends' values
// and ±1 at the critical points between, as tight as in one quadrant.
TEST(SinCos, AcrossQuadrantsIsTight) {
  set_working_precision(53);
  std::mt19937_64 rng(10);
  std::uniform_real_distribution<double> quadrant(-40, 40), frac(0.01, 0.98);
  for (int i = 0; i < 5000; ++i) {
    double lo = (std::floor(quadrant(rng)) + frac(rng)) * M_PI_2;
    double hi = (std::floor(lo / M_PI_2) + 1 + double(i % 5) + frac(rng)) * M_PI_2;
    check(lo, hi, true);
  }
}

TEST(SinCos, EndpointsWithinRoundingOfAMultipleOfHalfPi) {
  set_working_precision(53);
  for (long k = -40; k <= 40; ++k) {
    double p = double(k) * M_PI_2;  // within an ulp or so of kπ/2, on either side
    for (int steps = 0; steps < 6; ++steps) {
      double below = p, above = p;
      for (int s = 0; s < steps; ++s) {
        below = std::nextafter(below, -INFINITY);
        above = std::nextafter(above, INFINITY);
      }
      check(below, p, false);
      check(p, above, false);
      check(below, above, false);
      check(p - 1e-3, below, false);
      check(above, p + 1e-3, false);
    }
  }
}

TEST(SinCos, HigherPrecisionStaysSound) {
  set_working_precision(200);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> centre(-10, 10), w(0, 0.5);
  for (int i = 0; i < 2000; ++i) {
    double lo = centre(rng);
    check(lo, lo + w(rng), false);
  }
  set_working_precision(53);
}

}  // namespace
