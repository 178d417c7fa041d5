#include "sincos.h"

#include <cmath>

namespace aspects {

SinCos::SinCos() {
  mpfr_prec_t p = mpfr_get_default_prec();
  mpfr_inits2(p, s_lo_, c_lo_, s_hi_, c_hi_, static_cast<mpfr_ptr>(nullptr));
}

SinCos::~SinCos() { mpfr_clears(s_lo_, c_lo_, s_hi_, c_hi_, static_cast<mpfr_ptr>(nullptr)); }

// The test runs in double on [lo_d, hi_d] ⊇ [a]. For |t| <= 2^20, u = t / (π/2) computed
// in double is within 2^20/(π/2) · 2^-51 < 4e-10 of the exact quotient, so with a margin
// of 1e-9 an integer (a multiple of π/2) cannot hide in [u_lo, u_hi].
bool SinCos::inside_one_quadrant(const Interval& a, long& j) {
  double lo = a.lo_down(), hi = a.hi_up();
  const double limit = 1048576.0;  // 2^20
  if (!(lo >= -limit && hi <= limit)) return false;  // also rejects NaN
  const double margin = 1e-9;
  double u_lo = lo / M_PI_2 - margin, u_hi = hi / M_PI_2 + margin;
  double q = std::floor(u_lo);
  if (q != std::floor(u_hi)) return false;
  j = long(q);
  return true;
}

void SinCos::enclose(const Interval& a, Interval& s, Interval& c) {
  long j = 0;
  if (!inside_one_quadrant(a, j)) {
    mpfi_sin(s.get(), a.get());
    mpfi_cos(c.get(), a.get());
    return;
  }
  mpfr_srcptr lo = &a.get()->left;
  mpfr_srcptr hi = &a.get()->right;
  // Rounded to nearest, so the true value lies strictly between the neighbours of the
  // result (or equals it): one step outward makes each endpoint a bound.
  mpfr_sin_cos(s_lo_, c_lo_, lo, MPFR_RNDN);
  if (mpfr_equal_p(lo, hi)) {
    mpfr_set(s_hi_, s_lo_, MPFR_RNDN);
    mpfr_set(c_hi_, c_lo_, MPFR_RNDN);
  } else {
    mpfr_sin_cos(s_hi_, c_hi_, hi, MPFR_RNDN);
  }
  // On (jπ/2, (j+1)π/2): sin increases in quadrants 0 and 3 (mod 4), cos in 2 and 3.
  long quadrant = ((j % 4) + 4) % 4;
  bool sin_up = quadrant == 0 || quadrant == 3;
  bool cos_up = quadrant == 2 || quadrant == 3;
  mpfr_ptr s_min = sin_up ? s_lo_ : s_hi_;
  mpfr_ptr s_max = sin_up ? s_hi_ : s_lo_;
  mpfr_ptr c_min = cos_up ? c_lo_ : c_hi_;
  mpfr_ptr c_max = cos_up ? c_hi_ : c_lo_;
  mpfr_nextbelow(s_min);
  mpfr_nextabove(s_max);
  mpfr_nextbelow(c_min);
  mpfr_nextabove(c_max);
  mpfi_interv_fr(s.get(), s_min, s_max);
  mpfi_interv_fr(c.get(), c_min, c_max);
}

}  // namespace aspects
