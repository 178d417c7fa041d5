#include "numerics/sincos.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace aspects {

SinCos::SinCos() : memo_(1024), doubles_(mpfr_get_default_prec() == 53) {
  mpfr_prec_t p = mpfr_get_default_prec();
  mpfr_inits2(p, s_lo_, c_lo_, s_hi_, c_hi_, static_cast<mpfr_ptr>(nullptr));
}

SinCos::~SinCos() { mpfr_clears(s_lo_, c_lo_, s_hi_, c_hi_, static_cast<mpfr_ptr>(nullptr)); }

// The test runs in double on [lo_d, hi_d] ⊇ [a]. For |t| <= 2^20, u = t / (π/2) computed
// in double is within 2^20/(π/2) · 2^-51 < 4e-10 of the exact quotient, so with a margin
// of 1e-9 an integer (a multiple of π/2) cannot hide in [u_lo, u_hi].
bool SinCos::inside_one_quadrant(double lo, double hi, long& j) {
  const double limit = 1048576.0;  // 2^20
  if (!(lo >= -limit && hi <= limit)) return false;  // also rejects NaN
  const double margin = 1e-9;
  double u_lo = lo / M_PI_2 - margin, u_hi = hi / M_PI_2 + margin;
  double q = std::floor(u_lo);
  if (q != std::floor(u_hi)) return false;
  j = long(q);
  return true;
}

void SinCos::monotony(long j, bool& sin_up, bool& cos_up) {
  // On (jπ/2, (j+1)π/2): sin increases in quadrants 0 and 3 (mod 4), cos in 2 and 3.
  const long quadrant = ((j % 4) + 4) % 4;
  sin_up = quadrant == 0 || quadrant == 3;
  cos_up = quadrant == 2 || quadrant == 3;
}

void SinCos::enclose(const Interval& a, Interval& s, Interval& c) {
  if (doubles_) {
    DInterval ds, dc;
    if (enclose_doubles(a.lo_down(), a.hi_up(), ds, dc)) {
      mpfi_interv_d(s.get(), ds.lo, ds.hi);
      mpfi_interv_d(c.get(), dc.lo, dc.hi);
      return;
    }
  }
  long j = 0;
  if (doubles_ || !inside_one_quadrant(a.lo_down(), a.hi_up(), j)) {
    mpfi_sin(s.get(), a.get());
    mpfi_cos(c.get(), a.get());
    return;
  }
  bool sin_up, cos_up;
  monotony(j, sin_up, cos_up);
  enclose_mpfr(a, sin_up, cos_up, s, c);
}

bool SinCos::enclose_doubles(double lo, double hi, DInterval& s, DInterval& c) {
  long j = 0, j_hi = 0;
  if (!doubles_ || !inside_one_quadrant(lo, lo, j) || !inside_one_quadrant(hi, hi, j_hi))
    return false;
  double sl[2], sh[2], cl[2], ch[2];  // bounds at the lower [0] and upper [1] end
  arb_sin_cos(lo, sl[0], sh[0], cl[0], ch[0]);
  const int u = lo == hi ? 0 : 1;  // a point: both ends are one
  if (u == 1) arb_sin_cos(hi, sl[1], sh[1], cl[1], ch[1]);
  if (j == j_hi) {
    // Monotone on the quadrant: the minimum is at one end, the maximum at the other.
    bool sin_up, cos_up;
    monotony(j, sin_up, cos_up);
    s = {std::max(-1.0, sl[sin_up ? 0 : u]), std::min(1.0, sh[sin_up ? u : 0])};
    c = {std::max(-1.0, cl[cos_up ? 0 : u]), std::min(1.0, ch[cos_up ? u : 0])};
    return true;
  }
  // Ends in different quadrants (common enough that MPFI's mpfi_sin and mpfi_cos would
  // cost much): over [lo, hi] each function ranges over its values at the ends and at its
  // critical points inside, the multiples kπ/2 for k = j+1 .. j_hi, where it is ±1.
  s = {std::min(sl[0], sl[1]), std::max(sh[0], sh[1])};
  c = {std::min(cl[0], cl[1]), std::max(ch[0], ch[1])};
  for (long k = j + 1; k <= std::min(j_hi, j + 4); ++k) {
    switch (((k % 4) + 4) % 4) {
      case 0: c.hi = 1; break;   // cos 2mπ = 1
      case 1: s.hi = 1; break;   // sin (2m + 1/2)π = 1
      case 2: c.lo = -1; break;  // cos (2m + 1)π = −1
      case 3: s.lo = -1; break;  // sin (2m − 1/2)π = −1
    }
  }
  s = {std::max(-1.0, s.lo), std::min(1.0, s.hi)};
  c = {std::max(-1.0, c.lo), std::min(1.0, c.hi)};
  return true;
}

void SinCos::enclose_by_mpfi(const DInterval& a, DInterval& s, DInterval& c) {
  mpfi_arg_.set_hull(a.lo, a.hi);
  mpfi_sin(mpfi_sin_.get(), mpfi_arg_.get());
  mpfi_cos(mpfi_cos_.get(), mpfi_arg_.get());
  s = to_dinterval(mpfi_sin_);
  c = to_dinterval(mpfi_cos_);
}

void SinCos::arb_sin_cos(double t, double& s_lo, double& s_hi, double& c_lo, double& c_hi) {
  uint64_t bits;
  std::memcpy(&bits, &t, sizeof bits);
  Memo& m = memo_[(bits * 0x9E3779B97F4A7C15ull) >> 54];  // 1024 slots
  if (m.t != t) {  // NaN marks an empty slot; ±0 share one (same bounds)
    arb_.sin_cos(t, m.s_lo, m.s_hi, m.c_lo, m.c_hi);
    m.t = t;
  }
  s_lo = m.s_lo;
  s_hi = m.s_hi;
  c_lo = m.c_lo;
  c_hi = m.c_hi;
}

void SinCos::enclose_mpfr(const Interval& a, bool sin_up, bool cos_up, Interval& s, Interval& c) {
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
