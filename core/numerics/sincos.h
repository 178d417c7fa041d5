// Enclosures of sin and cos over one interval, computed together.
//
// The models use sin and cos of the same arguments (a joint angle, an orientation plus a
// constant), and MPFI computes each with two correctly rounded evaluations plus its own
// quadrant analysis. When [a] lies strictly inside one quadrant (no multiple of π/2 in
// it), sin and cos are both monotone there: their ranges are spanned by the values at the
// endpoints, and one sin-and-cos per endpoint gives all four. Otherwise MPFI decides,
// except at 53 bits when each end lies strictly inside a quadrant: then the critical
// points inside are the multiples of π/2 between the ends' quadrants.
// At 53 bits (endpoints are doubles) the endpoint values come from Arb's arb_sin_cos, a
// rigorous ball, rounded outward to doubles: several times cheaper than mpfr_sin_cos, and
// sin and cos are a large part of every evaluation. Above 53 bits, MPFR in RNDN with one
// step outward.
#pragma once

#include <mpfr.h>

#include <cmath>
#include <vector>

#include "numerics/arb_bounds.h"
#include "numerics/double_interval.h"
#include "numerics/interval.h"

namespace aspects {

class SinCos {
 public:
  SinCos();  // scratch at the current working precision
  ~SinCos();
  SinCos(const SinCos&) = delete;
  SinCos& operator=(const SinCos&) = delete;

  // s ⊇ {sin t : t ∈ a}, c ⊇ {cos t : t ∈ a}.
  void enclose(const Interval& a, Interval& s, Interval& c);
  // The same at 53 bits for a = [lo, hi] (doubles), in doubles. False, with nothing
  // computed, at another precision or when an end may be a multiple of π/2.
  bool enclose_doubles(double lo, double hi, DInterval& s, DInterval& c);
  // The same at 53 bits, in doubles: enclose_doubles, or MPFI's own sin and cos where an
  // end may be a multiple of π/2 (rare). The ends of enclose(Interval) at 53 bits.
  void enclose(const DInterval& a, DInterval& s, DInterval& c) {
    if (!enclose_doubles(a.lo, a.hi, s, c)) enclose_by_mpfi(a, s, c);
  }

 private:
  // True, with the quadrant index j ([lo, hi] ⊂ (jπ/2, (j+1)π/2)), when that is certain.
  static bool inside_one_quadrant(double lo, double hi, long& j);
  // Which of sin and cos increase on quadrant j.
  static void monotony(long j, bool& sin_up, bool& cos_up);
  void enclose_mpfr(const Interval& a, bool sin_up, bool cos_up, Interval& s, Interval& c);
  void enclose_by_mpfi(const DInterval& a, DInterval& s, DInterval& c);
  // Arb's bounds at one point, remembered: a box's children share an end with it, and
  // the proofs evaluate the same box several times (direct mapped on the point's bits).
  void arb_sin_cos(double t, double& s_lo, double& s_hi, double& c_lo, double& c_hi);
  struct Memo {
    double t = NAN, s_lo, s_hi, c_lo, c_hi;
  };
  std::vector<Memo> memo_;
  bool doubles_;  // the working precision is 53 bits
  mpfr_t s_lo_, c_lo_, s_hi_, c_hi_;
  ArbBounds arb_;
  Interval mpfi_arg_, mpfi_sin_, mpfi_cos_;  // enclose(DInterval) through MPFI
};

}  // namespace aspects
