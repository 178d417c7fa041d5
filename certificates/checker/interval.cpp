// interval.cpp — trusted core: the operations of interval.h on MPFI. When Ival::doubles
// (the speed layer, off with --trusted-only), each operation is its dbl:: namesake
// (interval_doubles.cpp), which computes the common cases itself and leaves the others
// (a false return) to the same MPFI functions, on the doubles' exact ends.
#include "interval_doubles.h"

namespace cc {

bool Ival::doubles = false;

void set_interval_precision(mpfr_prec_t bits, bool doubles) {
  mpfr_set_default_prec(bits);
  Ival::doubles = doubles && bits == 53;
}

namespace {

// r := f(a[, b]) by MPFI: directly, or on doubles through 53-bit scratch intervals holding
// the same ends exactly, the result rounded outward to doubles.
template <class F>
void by_mpfi(Ival& r, const Ival& a, const Ival* b, F f) {
  if (!Ival::doubles) return f(r.v, a.v, b ? b->v : a.v);
  mpfi_ptr x = dbl::scratch(0), y = dbl::scratch(1), z = dbl::scratch(2);
  dbl::to_mpfi(x, a);
  if (b) dbl::to_mpfi(y, *b);
  f(z, x, b ? y : x);
  dbl::from_mpfi(r, z);
}

}  // namespace

Ival::Ival() {
  if (doubles) l = h = NAN;
  else mpfi_init(v);
}
Ival::Ival(const Ival& o) : l(o.l), h(o.h) {
  if (doubles) return;
  mpfi_init2(v, mpfi_get_prec(o.v));
  mpfi_set(v, o.v);
}
Ival::~Ival() {
  if (!doubles) mpfi_clear(v);
}

void Ival::set(double a, double b) {
  if (doubles) return dbl::set(*this, a, b);
  mpfi_interv_d(v, a, b);
}
void Ival::set_end(End e, double x) {
  if (doubles) (e == Lo ? l : h) = x;
  else mpfr_set_d(e == Lo ? &v->left : &v->right, x, e == Lo ? MPFR_RNDD : MPFR_RNDU);
}
void Ival::entire() { set(-INFINITY, INFINITY); }
bool Ival::is_zero() const {
  return doubles ? l == 0 && h == 0 : mpfr_zero_p(&v->left) && mpfr_zero_p(&v->right);
}
int Ival::end_sign(End e) const {
  if (doubles) return dbl::end_sign(*this, e);
  return mpfr_sgn(e == Lo ? &v->left : &v->right);
}
int Ival::sign() const {
  if (empty()) return 0;
  if (end_sign(Lo) > 0) return 1;
  if (end_sign(Hi) < 0) return -1;
  return 0;
}
bool Ival::meet(const Ival& o) {
  intersect(*this, *this, o);
  return !empty();
}

static mpfr_ptr end_of(Ival& x, End e) { return e == Lo ? &x.v->left : &x.v->right; }
static mpfr_srcptr end_of(const Ival& x, End e) { return e == Lo ? &x.v->left : &x.v->right; }

bool less(const Ival& x, End ex, const Ival& y, End ey) {
  if (Ival::doubles) return dbl::less(x, ex, y, ey);
  return mpfr_less_p(end_of(x, ex), end_of(y, ey));
}
int cmp(const Ival& x, End e, double d) {
  if (Ival::doubles) return dbl::cmp(x, e, d);
  return mpfr_cmp_d(end_of(x, e), d);
}
void copy_end(Ival& dst, End ed, const Ival& src, End es) {
  if (Ival::doubles) return dst.set_end(ed, es == Lo ? src.l : src.h);
  mpfr_set(end_of(dst, ed), end_of(src, es), MPFR_RNDN);
}
void point(Ival& dst, const Ival& src, End es) {
  copy_end(dst, Hi, src, es);
  copy_end(dst, Lo, dst, Hi);
}
void get_end(mpfr_ptr out, const Ival& x, End e) {
  if (Ival::doubles) return void(mpfr_set_d(out, e == Lo ? x.l : x.h, MPFR_RNDN));
  mpfr_set(out, end_of(x, e), MPFR_RNDN);
}
void set_end(Ival& x, End e, mpfr_srcptr value) {
  const mpfr_rnd_t rnd = e == Lo ? MPFR_RNDD : MPFR_RNDU;
  if (Ival::doubles) return x.set_end(e, mpfr_get_d(value, rnd));
  mpfr_set(end_of(x, e), value, rnd);
}

void set_si(Ival& r, long k) {
  if (Ival::doubles) return r.set(double(k), double(k));  // |k| < 2^53 in the checker
  mpfi_set_si(r.v, k);
}

void add(Ival& r, const Ival& a, const Ival& b) {
  if (Ival::doubles && dbl::add(r, a, b)) return;
  by_mpfi(r, a, &b, [](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr y) { mpfi_add(z, x, y); });
}

void sub(Ival& r, const Ival& a, const Ival& b) {
  if (Ival::doubles && dbl::sub(r, a, b)) return;
  by_mpfi(r, a, &b, [](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr y) { mpfi_sub(z, x, y); });
}

void mul(Ival& r, const Ival& a, const Ival& b) {
  if (Ival::doubles && dbl::mul(r, a, b)) return;
  by_mpfi(r, a, &b, [](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr y) { mpfi_mul(z, x, y); });
}

void div(Ival& r, const Ival& a, const Ival& b) {
  if (Ival::doubles && dbl::div(r, a, b)) return;
  by_mpfi(r, a, &b, [](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr y) { mpfi_div(z, x, y); });
}

void add_d(Ival& r, const Ival& a, double d) {
  Ival t;
  t.set(d, d);
  add(r, a, t);
}

void mul_d(Ival& r, const Ival& a, double d) {
  if (Ival::doubles && dbl::mul_d(r, a, d)) return;
  Ival t;
  t.set(d, d);
  mul(r, a, t);
}

void si_sub(Ival& r, long k, const Ival& a) {
  Ival t;
  set_si(t, k);
  sub(r, t, a);
}

void neg(Ival& r, const Ival& a) {
  if (Ival::doubles) return dbl::neg(r, a);
  mpfi_neg(r.v, a.v);
}

void abs(Ival& r, const Ival& a) {
  if (Ival::doubles && dbl::abs(r, a)) return;
  by_mpfi(r, a, nullptr, [](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr) { mpfi_abs(z, x); });
}

void sqr(Ival& r, const Ival& a) {
  if (Ival::doubles && dbl::sqr(r, a)) return;
  by_mpfi(r, a, nullptr, [](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr) { mpfi_sqr(z, x); });
}

void inv(Ival& r, const Ival& a) {
  Ival one;
  set_si(one, 1);
  div(r, one, a);
}

void sqrt(Ival& r, const Ival& a) {
  if (Ival::doubles && dbl::sqrt(r, a)) return;
  by_mpfi(r, a, nullptr, [](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr) { mpfi_sqrt(z, x); });
}

void hull(Ival& r, const Ival& a, const Ival& b) {
  if (Ival::doubles) return dbl::hull(r, a, b);
  mpfi_union(r.v, a.v, b.v);
}

void intersect(Ival& r, const Ival& a, const Ival& b) {
  if (Ival::doubles) return dbl::intersect(r, a, b);
  mpfi_intersect(r.v, a.v, b.v);
}

void min(Ival& r, const Ival& a, const Ival& b) {
  if (Ival::doubles) return dbl::min(r, a, b);
  mpfr_min(&r.v->left, &a.v->left, &b.v->left, MPFR_RNDD);
  mpfr_min(&r.v->right, &a.v->right, &b.v->right, MPFR_RNDU);
}

void max(Ival& r, const Ival& a, const Ival& b) {
  if (Ival::doubles) return dbl::max(r, a, b);
  mpfr_max(&r.v->left, &a.v->left, &b.v->left, MPFR_RNDD);
  mpfr_max(&r.v->right, &a.v->right, &b.v->right, MPFR_RNDU);
}

bool one_ulp(const Ival& a) {
  if (Ival::doubles) return dbl::one_ulp(a);
  mpfr_t t;
  mpfr_init2(t, mpfi_get_prec(a.v));
  mpfr_set(t, &a.v->left, MPFR_RNDN);
  mpfr_nextabove(t);
  const bool r = mpfr_lessequal_p(&a.v->right, t);
  mpfr_clear(t);
  return r;
}

bool is_inside(const Ival& a, const Ival& b) {
  if (Ival::doubles) return dbl::is_inside(a, b);
  return mpfi_is_inside(a.v, b.v) > 0;
}

void mid(Ival& r, const Ival& a) {
  if (Ival::doubles) return dbl::mid(r, a);
  mpfi_mid(&r.v->left, a.v);
  mpfr_set(&r.v->right, &r.v->left, MPFR_RNDN);
}

void apply_fn(Fn f, Ival& r, const Ival& a) {
  by_mpfi(r, a, nullptr, [f](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr) {
    switch (f) {
      case Fn::Exp: mpfi_exp(z, x); break;
      case Fn::Log: mpfi_log(z, x); break;
      case Fn::Sin: mpfi_sin(z, x); break;
      case Fn::Cos: mpfi_cos(z, x); break;
      case Fn::Tan: mpfi_tan(z, x); break;
      case Fn::Asin: mpfi_asin(z, x); break;
      case Fn::Acos: mpfi_acos(z, x); break;
      case Fn::Atan: mpfi_atan(z, x); break;
    }
  });
}

void pow_ui(Ival& r, const Ival& a, unsigned long k) {
  if (Ival::doubles && k == 2 && a.l >= 0 && dbl::sqr(r, a)) return;  // x^2, as often
  by_mpfi(r, a, nullptr, [k](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr) {
    mpfr_pow_ui(&z->left, &x->left, k, MPFR_RNDD);
    mpfr_pow_ui(&z->right, &x->right, k, MPFR_RNDU);
  });
}

void rootn_ui(Ival& r, const Ival& a, unsigned long k) {
  if (Ival::doubles && k == 2 && dbl::sqrt(r, a)) return;
  by_mpfi(r, a, nullptr, [k](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr) {
    mpfr_rootn_ui(&z->left, &x->left, k, MPFR_RNDD);
    mpfr_rootn_ui(&z->right, &x->right, k, MPFR_RNDU);
  });
}

void log_hi(Ival& r, const Ival& a) {
  by_mpfi(r, a, nullptr, [](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr) {
    mpfr_set_inf(&z->left, -1);
    mpfr_log(&z->right, &x->right, MPFR_RNDU);
  });
}

void const_pi(Ival& r) {
  Ival none;
  by_mpfi(r, none, nullptr, [](mpfi_ptr z, mpfi_srcptr, mpfi_srcptr) { mpfi_const_pi(z); });
}

bool set_str(Ival& r, const std::string& decimal) {
  Ival none;
  int bad = 0;
  by_mpfi(r, none, nullptr, [&](mpfi_ptr z, mpfi_srcptr, mpfi_srcptr) {
    bad = mpfi_set_str(z, decimal.c_str(), 10);
  });
  return bad == 0;
}

}  // namespace cc
