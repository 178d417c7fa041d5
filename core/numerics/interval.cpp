#include "numerics/interval.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>

namespace aspects {

void set_working_precision(long bits) { mpfr_set_default_prec(bits); }
long working_precision() { return mpfr_get_default_prec(); }

bool Interval::from_string(Interval& out, const std::string& text) {
  // mpfi_set_str rounds the left end down and the right end up.
  if (mpfi_set_str(out.v_, text.c_str(), 10) != 0) return false;
  return !out.empty();
}

namespace {

// A number of at most 53 bits in the normal range of doubles is a double exactly: its
// bits are read off the limb. mpfr_get_d's general rounding path took 7 % of a search's
// profile. Anything else (more bits, zero, infinities, NaN, subnormal or overflowing
// exponents) goes through mpfr_get_d, rounded in `rnd`.
double get_double(mpfr_srcptr x, mpfr_rnd_t rnd) {
  static_assert(GMP_NUMB_BITS == 64, "one 64-bit limb holds a 53-bit significand");
  if (mpfr_get_prec(x) <= 53 && mpfr_regular_p(x)) {
    const mpfr_exp_t e = mpfr_get_exp(x);  // |x| = 0.1b…b × 2^e = 1.b…b × 2^(e−1)
    if (e >= -1021 && e <= 1024) {
      // The limb holds the significand from its top bit, zeros below the precision.
      const uint64_t significand = uint64_t(x->_mpfr_d[0]) >> 11;
      uint64_t bits = (uint64_t(e - 1 + 1023) << 52) | (significand & ((uint64_t(1) << 52) - 1));
      if (mpfr_signbit(x)) bits |= uint64_t(1) << 63;
      double d;
      std::memcpy(&d, &bits, sizeof d);
      return d;
    }
  }
  return mpfr_get_d(x, rnd);
}

}  // namespace

// The ends are read in place: mpfi_get_left/right would copy them into a temporary,
// an allocation per call in the innermost loops (8 % of the run time in a profile).
double Interval::lo_down() const {
  return get_double(&v_->left, MPFR_RNDD) + 0.0;  // MPFI keeps signed zeros; report +0
}

double Interval::hi_up() const {
  return get_double(&v_->right, MPFR_RNDU) + 0.0;  // MPFI stores a zero right end as -0
}

namespace {

// One MPFR temporary per thread, set to the precision asked (reallocated only when that
// changes): the same results as a fresh one, without an allocation per call.
mpfr_ptr scratch(mpfr_prec_t prec) {
  struct Scratch {
    mpfr_t t;
    Scratch() { mpfr_init2(t, MPFR_PREC_MIN); }
    ~Scratch() { mpfr_clear(t); }
  };
  thread_local Scratch s;
  if (mpfr_get_prec(s.t) != prec) mpfr_set_prec(s.t, prec);
  return s.t;
}

}  // namespace

double Interval::mid() const {
  double lo = lo_down(), hi = hi_up();
  if (mpfi_get_prec(v_) < 53 && std::isfinite(lo) && std::isfinite(hi)) {
    // Below 53 bits a double midpoint may not be representable: take MPFI's midpoint
    // at the interval's precision (exact as a double), so that points set from it
    // (Newton centres, split points, witnesses) stay points.
    mpfr_t m;
    mpfr_init2(m, mpfi_get_prec(v_));
    mpfi_mid(m, v_);
    double d = mpfr_get_d(m, MPFR_RNDN);
    mpfr_clear(m);
    return std::min(std::max(d, lo), hi) + 0.0;
  }
  if (std::isinf(lo) || std::isinf(hi)) {
    if (std::isinf(lo) && std::isinf(hi)) return 0.0;
    return std::isinf(lo) ? hi : lo;
  }
  double m = lo + 0.5 * (hi - lo);
  if (!(m >= lo)) m = lo;
  if (!(m <= hi)) m = hi;
  return m;
}

double Interval::width_up() const {
  mpfr_ptr t = scratch(mpfi_get_prec(v_));
  mpfi_diam_abs(t, v_);  // rounded up by MPFI
  return mpfr_get_d(t, MPFR_RNDU);
}

bool Interval::strictly_contains(const Interval& o) const {
  return mpfi_is_strictly_inside(o.v_, v_) > 0;
}

bool Interval::overlaps(const Interval& o) const {
  // Closed intervals share a point iff neither lies strictly beyond the other.
  return mpfr_lessequal_p(&v_->left, &o.v_->right) && mpfr_lessequal_p(&o.v_->left, &v_->right);
}

bool Interval::intersect(const Interval& o) {
  mpfi_intersect(v_, v_, o.v_);
  return !empty();
}

void Interval::set_entire() {
  mpfr_set_inf(&v_->left, -1);
  mpfr_set_inf(&v_->right, 1);
}

std::string Interval::str() const {
  char buf[128];
  std::snprintf(buf, sizeof buf, "[%.17g, %.17g]", lo_down(), hi_up());
  return buf;
}

double box_width(const Box& b) {
  double w = 0;
  for (const auto& x : b) w = std::max(w, x.width_up());
  return w;
}

}  // namespace aspects
