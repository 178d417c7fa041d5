// Shared helpers of the core tests: a small RAII MPFR number with arithmetic at a
// fixed high precision (the reference computations), and containment checks of an
// exact (MPFR) value in an MPFI interval.
#pragma once

#include <gmp.h>
#include <mpfr.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "model/expr.h"
#include "numerics/interval.h"

namespace aspects_test {

// Precision of every R created; the reference computations run at this precision.
inline mpfr_prec_t& ref_prec() {
  static mpfr_prec_t p = 256;
  return p;
}

// RAII MPFR value, round-to-nearest arithmetic at ref_prec().
class R {
 public:
  R() { mpfr_init2(v_, ref_prec()); mpfr_set_zero(v_, 1); }
  R(double d) { mpfr_init2(v_, ref_prec()); mpfr_set_d(v_, d, MPFR_RNDN); }  // exact
  R(int i) { mpfr_init2(v_, ref_prec()); mpfr_set_si(v_, i, MPFR_RNDN); }
  explicit R(const char* decimal) {
    mpfr_init2(v_, ref_prec());
    mpfr_set_str(v_, decimal, 10, MPFR_RNDN);
  }
  R(const R& o) { mpfr_init2(v_, mpfr_get_prec(o.v_)); mpfr_set(v_, o.v_, MPFR_RNDN); }
  R& operator=(const R& o) {
    if (this != &o) {
      mpfr_set_prec(v_, mpfr_get_prec(o.v_));
      mpfr_set(v_, o.v_, MPFR_RNDN);
    }
    return *this;
  }
  ~R() { mpfr_clear(v_); }
  static R pi() { R r; mpfr_const_pi(r.v_, MPFR_RNDN); return r; }

  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }
  double d() const { return mpfr_get_d(v_, MPFR_RNDN); }

  friend R operator+(const R& a, const R& b) { R r; mpfr_add(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
  friend R operator-(const R& a, const R& b) { R r; mpfr_sub(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
  friend R operator*(const R& a, const R& b) { R r; mpfr_mul(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
  friend R operator/(const R& a, const R& b) { R r; mpfr_div(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
  friend R operator-(const R& a) { R r; mpfr_neg(r.v_, a.v_, MPFR_RNDN); return r; }
  friend bool operator<(const R& a, const R& b) { return mpfr_less_p(a.v_, b.v_); }
  friend bool operator<=(const R& a, const R& b) { return mpfr_lessequal_p(a.v_, b.v_); }
  friend bool operator>(const R& a, const R& b) { return mpfr_greater_p(a.v_, b.v_); }
  friend bool operator>=(const R& a, const R& b) { return mpfr_greaterequal_p(a.v_, b.v_); }

#define ASPECTS_TEST_R_FN(name, call)                                  \
  friend R name(const R& a) { R r; call(r.v_, a.v_, MPFR_RNDN); return r; }
  ASPECTS_TEST_R_FN(sin, mpfr_sin)
  ASPECTS_TEST_R_FN(cos, mpfr_cos)
  ASPECTS_TEST_R_FN(sqrt, mpfr_sqrt)
  ASPECTS_TEST_R_FN(sqr, mpfr_sqr)
  ASPECTS_TEST_R_FN(abs, mpfr_abs)
  ASPECTS_TEST_R_FN(acos, mpfr_acos)
#undef ASPECTS_TEST_R_FN
  friend R atan2(const R& y, const R& x) { R r; mpfr_atan2(r.v_, y.v_, x.v_, MPFR_RNDN); return r; }

  std::string str(int digits = 25) const {
    char buf[256];
    mpfr_snprintf(buf, sizeof buf, "%.*Rg", digits, v_);
    return buf;
  }

 private:
  mpfr_t v_;
};

// Is the exact value v inside the closed interval x?
inline bool interval_contains(const aspects::Interval& x, mpfr_srcptr v) {
  if (x.empty() || mpfr_nan_p(v)) return false;
  return mpfr_lessequal_p(&x.get()->left, v) && mpfr_lessequal_p(v, &x.get()->right);
}
inline bool interval_contains(const aspects::Interval& x, const R& v) {
  return interval_contains(x, v.get());
}

inline std::string interval_str(const aspects::Interval& x, int digits = 20) {
  char buf[512];
  mpfr_snprintf(buf, sizeof buf, "[%.*Rg, %.*Rg]", digits, &x.get()->left, digits,
                &x.get()->right);
  return buf;
}

inline std::string mpfr_str(mpfr_srcptr v, int digits = 25) {
  char buf[256];
  mpfr_snprintf(buf, sizeof buf, "%.*Rg", digits, v);
  return buf;
}

// Smallest interval with double endpoints holding [c - r, c + r] (outward rounded).
inline aspects::Interval ball(const R& c, double r) {
  R lo = c - R(r), hi = c + R(r);
  double l = mpfr_get_d(lo.get(), MPFR_RNDD), h = mpfr_get_d(hi.get(), MPFR_RNDU);
  return aspects::Interval(l, h);
}

// [c - rl, c + rh] outward rounded to doubles.
inline aspects::Interval ball2(const R& c, double rl, double rh) {
  R lo = c - R(rl), hi = c + R(rh);
  double l = mpfr_get_d(lo.get(), MPFR_RNDD), h = mpfr_get_d(hi.get(), MPFR_RNDU);
  return aspects::Interval(l, h);
}

inline double uniform(std::mt19937& g, double lo, double hi) {
  double x = std::uniform_real_distribution<double>(lo, hi)(g);
  if (x < lo) x = lo;
  if (x > hi) x = hi;
  return x;
}

}  // namespace aspects_test

namespace aspects_test {

// The exact value of one DAG operation at a point, rounded with rnd into out (MPFR is
// correctly rounded). Returns false where the operation is undefined.
inline bool exact_op(aspects::Op op, int k, mpfr_ptr out, mpfr_srcptr a, mpfr_srcptr b,
                     mpfr_rnd_t rnd) {
  using aspects::Op;
  switch (op) {
    case Op::Add: mpfr_add(out, a, b, rnd); return true;
    case Op::Sub: mpfr_sub(out, a, b, rnd); return true;
    case Op::Mul: mpfr_mul(out, a, b, rnd); return true;
    case Op::Div:
      if (mpfr_zero_p(b)) return false;
      mpfr_div(out, a, b, rnd);
      return true;
    case Op::Min: mpfr_min(out, a, b, rnd); return true;
    case Op::Max: mpfr_max(out, a, b, rnd); return true;
    case Op::Neg: mpfr_neg(out, a, rnd); return true;
    case Op::Sqr: mpfr_sqr(out, a, rnd); return true;
    case Op::Sqrt:
      if (mpfr_sgn(a) < 0) return false;
      mpfr_sqrt(out, a, rnd);
      return true;
    case Op::Sin: mpfr_sin(out, a, rnd); return true;
    case Op::Cos: mpfr_cos(out, a, rnd); return true;
    case Op::Tan: mpfr_tan(out, a, rnd); return true;
    case Op::Exp: mpfr_exp(out, a, rnd); return true;
    case Op::Log:
      if (mpfr_sgn(a) <= 0) return false;
      mpfr_log(out, a, rnd);
      return true;
    case Op::Abs: mpfr_abs(out, a, rnd); return true;
    case Op::Asin:
      if (mpfr_cmpabs_ui(a, 1) > 0) return false;
      mpfr_asin(out, a, rnd);
      return true;
    case Op::Acos:
      if (mpfr_cmpabs_ui(a, 1) > 0) return false;
      mpfr_acos(out, a, rnd);
      return true;
    case Op::Atan: mpfr_atan(out, a, rnd); return true;
    case Op::Pow:
      if (k < 0 && mpfr_zero_p(a)) return false;
      mpfr_pow_si(out, a, k, rnd);
      return true;
    case Op::Sign: mpfr_set_si(out, mpfr_sgn(a), rnd); return true;
    case Op::Step:  // 1 if a < b, 0 if a > b; callers skip a = b (unspecified there)
      mpfr_set_si(out, mpfr_cmp(a, b) < 0 ? 1 : 0, rnd);
      return true;
    default: return false;
  }
}

}  // namespace aspects_test
