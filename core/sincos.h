// Enclosures of sin and cos over one interval, computed together.
//
// The models use sin and cos of the same arguments (a joint angle, an orientation plus a
// constant), and MPFI computes each with two correctly rounded evaluations plus its own
// quadrant analysis. When [a] lies strictly inside one quadrant (no multiple of π/2 in
// it), sin and cos are both monotone there: their ranges are spanned by the values at the
// endpoints, and one mpfr_sin_cos per endpoint gives all four. Otherwise MPFI decides.
#pragma once

#include <mpfr.h>

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
  mpfr_t s_lo_, c_lo_, s_hi_, c_hi_;
};

}  // namespace aspects
