// ival.h — the checker's only interval type: an owning wrapper around one MPFI interval
// at the certificate's precision (mpfr_set_default_prec is set once, before any Ival
// exists), plus the few endpoint helpers the checker needs. Every interval result that
// feeds a verdict is produced by an MPFI operation (outward rounded); the helpers below
// only read endpoints with explicit directed rounding.
#pragma once

#include <mpfi.h>

namespace cc {

struct Ival {
  mpfi_t v;
  Ival() { mpfi_init(v); }
  Ival(const Ival& o) { mpfi_init2(v, mpfi_get_prec(o.v)); mpfi_set(v, o.v); }
  Ival& operator=(const Ival& o) {
    if (this != &o) mpfi_set(v, o.v);
    return *this;
  }
  ~Ival() { mpfi_clear(v); }
  operator mpfi_ptr() { return v; }
  operator mpfi_srcptr() const { return v; }
  mpfr_ptr L() { return &v->left; }
  mpfr_ptr R() { return &v->right; }
  mpfr_srcptr L() const { return &v->left; }
  mpfr_srcptr R() const { return &v->right; }
  // Endpoints as doubles, rounded outward (lo down, hi up).
  double lo() const { return mpfr_get_d(&v->left, MPFR_RNDD); }
  double hi() const { return mpfr_get_d(&v->right, MPFR_RNDU); }
  void set(double lo, double hi) { mpfi_interv_d(v, lo, hi); }
  void entire() { mpfr_set_inf(&v->left, -1); mpfr_set_inf(&v->right, 1); }
  bool empty() const { return mpfi_nan_p(v) || mpfi_is_empty(v); }
  bool bounded() const { return !mpfi_nan_p(v) && mpfi_bounded_p(v); }
  bool has_zero() const { return mpfi_has_zero(v) > 0; }
  // Certain sign: +1 when lo > 0, -1 when hi < 0, else 0.
  int sign() const {
    if (empty()) return 0;
    if (mpfr_sgn(&v->left) > 0) return 1;
    if (mpfr_sgn(&v->right) < 0) return -1;
    return 0;
  }
  // this ∩= o; false when the result is empty.
  bool meet(mpfi_srcptr o) {
    mpfi_intersect(v, v, o);
    return !empty();
  }
};

}  // namespace cc
