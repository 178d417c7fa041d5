// Enclosures of sin and cos over one interval, computed together.
//
// The models use sin and cos of the same arguments (a joint angle, an orientation plus a
// constant), and MPFI computes each with two correctly rounded evaluations plus its own
// quadrant analysis. When [a] lies strictly inside one quadrant (no multiple of π/2 in
// it), sin and cos are both monotone there: their ranges are spanned by the values at the
// endpoints, and one sin-and-cos per endpoint gives all four. Otherwise MPFI decides.
// At 53 bits (endpoints are doubles) the endpoint values come from Arb's arb_sin_cos, a
// rigorous ball, rounded outward to doubles: about four times faster than mpfr_sin_cos,
// which was a fifth of the run time (bench/RESULTS.md). Above 53 bits, MPFR in RNDN with
// one step outward.
#pragma once

#include <mpfr.h>

#include "arb_bounds.h"
#include "interval.h"

namespace aspects {

class SinCos {
 public:
  SinCos();  // scratch at the current working precision
  ~SinCos();
  SinCos(const SinCos&) = delete;
  SinCos& operator=(const SinCos&) = delete;

  // s ⊇ {sin t : t ∈ a}, c ⊇ {cos t : t ∈ a}.
  void enclose(const Interval& a, Interval& s, Interval& c);

 private:
  // True, with the quadrant index j (a ⊂ (jπ/2, (j+1)π/2)), when that is certain.
  static bool inside_one_quadrant(const Interval& a, long& j);
  void enclose_mpfr(const Interval& a, bool sin_up, bool cos_up, Interval& s, Interval& c);
  bool doubles_;  // the working precision is 53 bits
  mpfr_t s_lo_, c_lo_, s_hi_, c_hi_;
  ArbBounds arb_;
};

}  // namespace aspects
