// Direct access to the MPFR endpoints of an MPFI interval, and the constant intervals
// the evaluator's kernels intersect with. Internal to the MPFI primitives
// (core/numerics/evaluator_ops.h).
#pragma once

#include "numerics/interval.h"

namespace aspects {
namespace ends {

inline mpfr_ptr L(Interval& x) { return &x.get()->left; }
inline mpfr_ptr R(Interval& x) { return &x.get()->right; }
inline mpfr_srcptr L(const Interval& x) { return &x.get()->left; }
inline mpfr_srcptr R(const Interval& x) { return &x.get()->right; }

inline void set_half_line_pos(Interval& x) {  // [0, +inf]
  mpfr_set_zero(L(x), 1);
  mpfr_set_inf(R(x), 1);
}

inline void set_unit(Interval& x) {  // [-1, 1]
  mpfr_set_si(L(x), -1, MPFR_RNDD);
  mpfr_set_si(R(x), 1, MPFR_RNDU);
}

}  // namespace ends
}  // namespace aspects
