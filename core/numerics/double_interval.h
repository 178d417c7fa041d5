// Intervals with double endpoints and outward rounding, for a working precision of 53
// bits, where every MPFI endpoint is a double. Each operation rounds its ends in the
// directed way MPFR does (RNDD for the lower end, RNDU for the upper), without changing
// the FPU's rounding mode: the result rounded to nearest is computed, an error-free
// transformation (TwoSum, or an FMA residual) gives the sign of the rounding error, and the
// end steps one ulp outward only when the rounded value lies on the wrong side of the
// exact one. So the ends are the ones MPFI computes at 53 bits, bit for bit. Where the
// residual could be inexact (results near the underflow threshold) the end steps outward
// unconditionally: still sound, one ulp wider. An overflowing end becomes the largest
// finite double on the side of the exact value, or the infinity beyond it.
//
// Callers keep every value finite: the evaluator (core/model/interval_eval.h) hands any
// infinite or NaN value back to MPFI.
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace aspects {

struct DInterval {
  double lo, hi;
};

namespace dround {

// The neighbours of a double, from its bits (std::nextafter is a library call, and these
// run several times per operation).
inline double next_up(double x) {
  if (!(x < INFINITY)) return x;    // +∞ and NaN stay
  if (x == 0) return DBL_TRUE_MIN;  // from either zero
  uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  b += x > 0 ? 1 : -1;  // the magnitude's next encoding up (x > 0) or down (x < 0)
  std::memcpy(&x, &b, sizeof x);
  return x;
}
inline double next_down(double x) { return -next_up(-x); }

// Below this magnitude an FMA residual may underflow (lose bits): step outward regardless.
constexpr double kTiny = 0x1p-900;

// x is the rounded-to-nearest value of a finite exact result; err = exact − x when known.
inline double down_from(double x, double err) {
  if (std::isinf(x)) return x > 0 ? DBL_MAX : x;  // overflow: the exact value is finite
  return err < 0 ? next_down(x) : x;
}
inline double up_from(double x, double err) {
  if (std::isinf(x)) return x < 0 ? -DBL_MAX : x;
  return err > 0 ? next_up(x) : x;
}

// TwoSum (Knuth): exact error of a + b for any finite a, b without overflow.
inline double sum_error(double a, double b, double s) {
  double bb = s - a;
  return (a - (s - bb)) + (b - bb);
}
inline double add_down(double a, double b) {
  double s = a + b;
  return down_from(s, sum_error(a, b, s));
}
inline double add_up(double a, double b) {
  double s = a + b;
  return up_from(s, sum_error(a, b, s));
}
inline double sub_down(double a, double b) { return add_down(a, -b); }
inline double sub_up(double a, double b) { return add_up(a, -b); }

inline double mul_down(double a, double b) {
  double p = a * b;
  if (a == 0 || b == 0) return 0;
  if (std::fabs(p) < kTiny) return next_down(p);
  return down_from(p, std::fma(a, b, -p));
}
inline double mul_up(double a, double b) {
  double p = a * b;
  if (a == 0 || b == 0) return 0;
  if (std::fabs(p) < kTiny) return next_up(p);
  return up_from(p, std::fma(a, b, -p));
}

// b != 0. a − q·b is exact (an FMA) away from underflow; a/b − q has its sign times b's.
inline double div_down(double a, double b) {
  double q = a / b;
  if (a == 0) return 0;
  if (std::fabs(q) < kTiny || std::fabs(a) < kTiny) return next_down(q);
  double r = std::fma(-q, b, a);
  return down_from(q, b > 0 ? r : -r);
}
inline double div_up(double a, double b) {
  double q = a / b;
  if (a == 0) return 0;
  if (std::fabs(q) < kTiny || std::fabs(a) < kTiny) return next_up(q);
  double r = std::fma(-q, b, a);
  return up_from(q, b > 0 ? r : -r);
}

// a >= 0. √a − s has the sign of a − s².
inline double sqrt_down(double a) {
  double s = std::sqrt(a);
  if (a == 0) return 0;
  if (a < kTiny) return next_down(s);
  return down_from(s, std::fma(-s, s, a));
}
inline double sqrt_up(double a) {
  double s = std::sqrt(a);
  if (a == 0) return 0;
  if (a < kTiny) return next_up(s);
  return up_from(s, std::fma(-s, s, a));
}

}  // namespace dround

inline bool is_empty(const DInterval& x) { return !(x.lo <= x.hi); }
inline bool is_finite(const DInterval& x) { return std::isfinite(x.lo) && std::isfinite(x.hi); }
inline bool has_zero(const DInterval& x) { return x.lo <= 0 && x.hi >= 0; }
inline bool same(const DInterval& x, const DInterval& y) { return x.lo == y.lo && x.hi == y.hi; }
inline double width_up(const DInterval& x) { return dround::sub_up(x.hi, x.lo); }
// A double inside x, as Interval::mid at 53 bits (a choice, verified afterwards).
inline double mid(const DInterval& x) {
  if (std::isinf(x.lo) || std::isinf(x.hi)) {
    if (std::isinf(x.lo) && std::isinf(x.hi)) return 0.0;
    return std::isinf(x.lo) ? x.hi : x.lo;
  }
  double m = x.lo + 0.5 * (x.hi - x.lo);
  if (!(m >= x.lo)) m = x.lo;
  if (!(m <= x.hi)) m = x.hi;
  return m;
}

inline DInterval add(const DInterval& a, const DInterval& b) {
  return {dround::add_down(a.lo, b.lo), dround::add_up(a.hi, b.hi)};
}
inline DInterval sub(const DInterval& a, const DInterval& b) {
  return {dround::sub_down(a.lo, b.hi), dround::sub_up(a.hi, b.lo)};
}
inline DInterval neg(const DInterval& a) { return {-a.hi, -a.lo}; }

// The hull of x ∘ y over the four pairs of ends, each rounded down by `down` and up by `up`.
// Rounding is monotone, so the least rounded-down value is the rounded-down least value:
// for × and / (monotone in each argument on the boxes given) the same ends as MPFI's case
// analysis.
template <class Down, class Up>
inline DInterval over_ends(const DInterval& a, const DInterval& b, Down down, Up up) {
  return {std::min(std::min(down(a.lo, b.lo), down(a.lo, b.hi)),
                   std::min(down(a.hi, b.lo), down(a.hi, b.hi))),
          std::max(std::max(up(a.lo, b.lo), up(a.lo, b.hi)),
                   std::max(up(a.hi, b.lo), up(a.hi, b.hi)))};
}

inline DInterval mul(const DInterval& a, const DInterval& b) {
  using namespace dround;
  if (a.lo >= 0 && b.lo >= 0) return {mul_down(a.lo, b.lo), mul_up(a.hi, b.hi)};
  return over_ends(a, b, [](double x, double y) { return mul_down(x, y); },
                   [](double x, double y) { return mul_up(x, y); });
}

// 0 ∉ b.
inline DInterval div(const DInterval& a, const DInterval& b) {
  using namespace dround;
  return over_ends(a, b, [](double x, double y) { return div_down(x, y); },
                   [](double x, double y) { return div_up(x, y); });
}

inline DInterval sqr(const DInterval& a) {
  using namespace dround;
  if (a.lo >= 0) return {mul_down(a.lo, a.lo), mul_up(a.hi, a.hi)};
  if (a.hi <= 0) return {mul_down(a.hi, a.hi), mul_up(a.lo, a.lo)};
  return {0.0, std::max(mul_up(a.lo, a.lo), mul_up(a.hi, a.hi))};
}

// a.lo >= 0.
inline DInterval sqrt(const DInterval& a) { return {dround::sqrt_down(a.lo), dround::sqrt_up(a.hi)}; }

// x = x ∩ y; false when empty.
inline bool meet(DInterval& x, const DInterval& y) {
  x.lo = std::max(x.lo, y.lo);
  x.hi = std::min(x.hi, y.hi);
  return x.lo <= x.hi;
}

inline DInterval hull(const DInterval& x, const DInterval& y) {
  return {std::min(x.lo, y.lo), std::max(x.hi, y.hi)};
}

}  // namespace aspects
