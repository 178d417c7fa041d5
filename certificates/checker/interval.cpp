// interval.cpp — trusted core: the operations of interval.h. On doubles, an end is the
// result rounded to nearest, moved one ulp outward exactly when an error-free
// transformation says the exact value lies on the other side: TwoSum for sums, an FMA
// residual for products, quotients and square roots. Those residuals are exact for finite
// operands unless a result is near the underflow threshold, which goes to MPFI instead.
#include "interval.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

namespace cc {

bool Ival::doubles = false;

void set_interval_precision(mpfr_prec_t bits, bool doubles) {
  mpfr_set_default_prec(bits);
  Ival::doubles = doubles && bits == 53;
}

namespace {

const double kTiny = 0x1p-960;  // below it, a residual may not be exact

double next_up(double x) {  // x finite
  if (x == 0) return 0x1p-1074;
  uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  b = x > 0 ? b + 1 : b - 1;  // the magnitude grows (x > 0) or shrinks (x < 0)
  std::memcpy(&x, &b, sizeof b);
  return x;
}
double next_down(double x) { return -next_up(-x); }

int sgn(double e) { return (e > 0) - (e < 0); }
// s rounded to nearest, err the sign of the exact value minus s: the directed roundings.
double down(double s, int err) { return err < 0 ? next_down(s) : s; }
double up(double s, int err) { return err > 0 ? next_up(s) : s; }

// A sum x + y rounded to nearest as s (finite), and the sign of its error (TwoSum).
int sum_err(double x, double y, double s) {
  const double bb = s - x;
  return sgn((x - (s - bb)) + (y - bb));
}

// The sign of x·y − fl(x·y); false when fl(x·y) is not finite or too small to tell.
bool product_err(double x, double y, double p, int& err) {
  if (x == 0 || y == 0) return err = 0, true;
  if (!std::isfinite(p) || std::fabs(p) < kTiny) return false;
  err = sgn(std::fma(x, y, -p));
  return true;
}

// The sign of x/y − fl(x/y) (y ≠ 0): x − q·y is exact, of the sign of y·(x/y − q).
bool quotient_err(double x, double y, double q, int& err) {
  if (x == 0) return err = 0, true;
  if (!std::isfinite(q) || std::fabs(q) < kTiny || std::fabs(x) < kTiny) return false;
  err = sgn(std::fma(-q, y, x)) * sgn(y);
  return true;
}

bool finite(const Ival& a) { return std::isfinite(a.l) && std::isfinite(a.h); }
bool proper(const Ival& a) { return finite(a) && a.l <= a.h; }  // also not empty

// MPFI's scratch intervals at 53 bits, per thread, for the slow path of the doubles.
struct Scratch {
  mpfi_t a, b, r;
  Scratch() {
    mpfi_init2(a, 53);
    mpfi_init2(b, 53);
    mpfi_init2(r, 53);
  }
  ~Scratch() {
    mpfi_clear(a);
    mpfi_clear(b);
    mpfi_clear(r);
  }
};
thread_local Scratch scratch;

void to_mpfi(mpfi_ptr out, const Ival& a) {
  mpfr_set_d(&out->left, a.l, MPFR_RNDD);  // exact at 53 bits, NaN included
  mpfr_set_d(&out->right, a.h, MPFR_RNDU);
}
void from_mpfi(Ival& r, mpfi_srcptr x) {
  r.l = mpfr_get_d(&x->left, MPFR_RNDD);
  r.h = mpfr_get_d(&x->right, MPFR_RNDU);
}

// r := f(a[, b]) by MPFI: on the doubles through the scratch, or directly.
template <class F>
void by_mpfi(Ival& r, const Ival& a, const Ival* b, F f) {
  if (!Ival::doubles) return f(r.v, a.v, b ? b->v : a.v);
  Scratch& s = scratch;
  to_mpfi(s.a, a);
  if (b) to_mpfi(s.b, *b);
  f(s.r, s.a, b ? s.b : s.a);
  from_mpfi(r, s.r);
}

// r := [op(xl, yl), op(xh, yh)], each rounded outward; false when a residual cannot tell the
// rounding.
template <class Op, class Err>
bool ends(Ival& r, double xl, double yl, double xh, double yh, Op op, Err err) {
  const double zl = op(xl, yl), zh = op(xh, yh);
  int el = 0, eh = 0;
  if (!err(xl, yl, zl, el) || !err(xh, yh, zh, eh)) return false;
  r.l = down(zl, el);
  r.h = up(zh, eh);
  return true;
}

// a·b from the corners the signs select (the usual nine cases): one product an end unless
// both straddle 0. Each end is the least (greatest) corner rounded down (up).
bool product(Ival& r, const Ival& a, const Ival& b) {
  auto op = [](double x, double y) { return x * y; };
  if (a.l >= 0)
    return ends(r, b.l >= 0 ? a.l : a.h, b.l, b.h <= 0 ? a.l : a.h, b.h, op, product_err);
  if (a.h <= 0)
    return ends(r, b.h <= 0 ? a.h : a.l, b.h, b.l >= 0 ? a.h : a.l, b.l, op, product_err);
  if (b.l >= 0) return ends(r, a.l, b.h, a.h, b.h, op, product_err);  // a straddles 0
  if (b.h <= 0) return ends(r, a.h, b.l, a.l, b.l, op, product_err);
  Ival p, q;  // both straddle 0: lo is a.l·b.h or a.h·b.l, hi a.l·b.l or a.h·b.h
  if (!ends(p, a.l, b.h, a.l, b.l, op, product_err)) return false;
  if (!ends(q, a.h, b.l, a.h, b.h, op, product_err)) return false;
  r.l = std::min(p.l, q.l);
  r.h = std::max(p.h, q.h);
  return true;
}

// a/b for b > 0 or b < 0, from the two corners the signs select.
bool quotient(Ival& r, const Ival& a, const Ival& b) {
  const double nl = b.l > 0 ? a.l : a.h, nh = b.l > 0 ? a.h : a.l;  // the ends' numerators
  auto op = [](double x, double y) { return x / y; };
  return ends(r, nl, nl >= 0 ? b.h : b.l, nh, nh >= 0 ? b.l : b.h, op, quotient_err);
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
  if (!doubles) return void(mpfi_interv_d(v, a, b));
  if (b < a) std::swap(a, b);  // as mpfi_interv_d
  l = a;
  h = b;
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
  if (doubles) return sgn(e == Lo ? l : h);
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

static mpfr_srcptr end_of(const Ival& x, End e) { return e == Lo ? &x.v->left : &x.v->right; }
static double dend(const Ival& x, End e) { return e == Lo ? x.l : x.h; }

bool less(const Ival& x, End ex, const Ival& y, End ey) {
  if (Ival::doubles) return dend(x, ex) < dend(y, ey);
  return mpfr_less_p(end_of(x, ex), end_of(y, ey));
}
int cmp(const Ival& x, End e, double d) {
  if (Ival::doubles) return sgn(dend(x, e) - d) * !std::isnan(dend(x, e));
  return mpfr_cmp_d(end_of(x, e), d);
}
void copy_end(Ival& dst, End ed, const Ival& src, End es) {
  if (Ival::doubles) (ed == Lo ? dst.l : dst.h) = dend(src, es);
  else mpfr_set(ed == Lo ? &dst.v->left : &dst.v->right, end_of(src, es), MPFR_RNDN);
}
void point(Ival& dst, const Ival& src, End es) {
  copy_end(dst, Hi, src, es);
  copy_end(dst, Lo, dst, Hi);
}
void get_end(mpfr_ptr out, const Ival& x, End e) {
  if (Ival::doubles) mpfr_set_d(out, dend(x, e), MPFR_RNDN);
  else mpfr_set(out, end_of(x, e), MPFR_RNDN);
}
void set_end(Ival& x, End e, mpfr_srcptr value) {
  const mpfr_rnd_t rnd = e == Lo ? MPFR_RNDD : MPFR_RNDU;
  if (Ival::doubles) (e == Lo ? x.l : x.h) = mpfr_get_d(value, rnd);
  else mpfr_set(e == Lo ? &x.v->left : &x.v->right, value, rnd);
}

void set_si(Ival& r, long k) {
  if (Ival::doubles) r.l = r.h = double(k);  // |k| < 2^53 in the checker
  else mpfi_set_si(r.v, k);
}

void add(Ival& r, const Ival& a, const Ival& b) {
  if (Ival::doubles && finite(a) && finite(b)) {
    const double lo = a.l + b.l, hi = a.h + b.h;
    if (std::isfinite(lo) && std::isfinite(hi)) {
      const double rl = down(lo, sum_err(a.l, b.l, lo));
      r.h = up(hi, sum_err(a.h, b.h, hi));
      r.l = rl;
      return;
    }
  }
  by_mpfi(r, a, &b, [](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr y) { mpfi_add(z, x, y); });
}

void sub(Ival& r, const Ival& a, const Ival& b) {
  if (Ival::doubles && finite(a) && finite(b)) {
    const double lo = a.l - b.h, hi = a.h - b.l;
    if (std::isfinite(lo) && std::isfinite(hi)) {
      const double rl = down(lo, sum_err(a.l, -b.h, lo));
      r.h = up(hi, sum_err(a.h, -b.l, hi));
      r.l = rl;
      return;
    }
  }
  by_mpfi(r, a, &b, [](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr y) { mpfi_sub(z, x, y); });
}

void mul(Ival& r, const Ival& a, const Ival& b) {
  if (Ival::doubles && proper(a) && proper(b) && product(r, a, b)) return;
  by_mpfi(r, a, &b, [](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr y) { mpfi_mul(z, x, y); });
}

void div(Ival& r, const Ival& a, const Ival& b) {
  if (Ival::doubles && proper(a) && proper(b) && (b.l > 0 || b.h < 0) && quotient(r, a, b))
    return;
  by_mpfi(r, a, &b, [](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr y) { mpfi_div(z, x, y); });
}

void add_d(Ival& r, const Ival& a, double d) {
  Ival t;
  t.set(d, d);
  add(r, a, t);
}

void mul_d(Ival& r, const Ival& a, double d) {  // the preconditioners' products: two corners
  auto op = [](double x, double y) { return x * y; };
  const double xl = d >= 0 ? a.l : a.h, xh = d >= 0 ? a.h : a.l;
  if (Ival::doubles && proper(a) && ends(r, xl, d, xh, d, op, product_err)) return;
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
  if (!Ival::doubles) return mpfi_neg(r.v, a.v), void();
  const double lo = -a.h;
  r.h = -a.l;
  r.l = lo;
}

void abs(Ival& r, const Ival& a) {
  if (!Ival::doubles || !proper(a)) {
    by_mpfi(r, a, nullptr, [](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr) { mpfi_abs(z, x); });
  } else if (a.l >= 0) {
    r = a;
  } else if (a.h <= 0) {
    neg(r, a);
  } else {
    r.h = std::max(-a.l, a.h);
    r.l = 0;
  }
}

void sqr(Ival& r, const Ival& a) {
  if (Ival::doubles && proper(a)) {
    const double m = a.l >= 0 ? a.l : a.h <= 0 ? -a.h : 0;  // the least |x|
    const double M = std::max(-a.l, a.h);                   // the largest
    const double lo = m * m, hi = M * M;
    int el = 0, eh = 0;
    if (product_err(m, m, lo, el) && product_err(M, M, hi, eh)) {
      r.l = down(lo, el);
      r.h = up(hi, eh);
      return;
    }
  }
  by_mpfi(r, a, nullptr, [](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr) { mpfi_sqr(z, x); });
}

void inv(Ival& r, const Ival& a) {
  Ival one;
  set_si(one, 1);
  div(r, one, a);
}

void sqrt(Ival& r, const Ival& a) {
  if (Ival::doubles && proper(a) && a.l >= 0) {
    // sqrt(x) − s has the sign of x − s², which the FMA residual gives exactly.
    auto root = [](double x, int& err) {
      const double s = std::sqrt(x);
      err = x == 0 ? 0 : sgn(std::fma(-s, s, x));
      return s;
    };
    if ((a.l == 0 || a.l >= kTiny) && (a.h == 0 || a.h >= kTiny)) {
      int el = 0, eh = 0;
      const double lo = root(a.l, el), hi = root(a.h, eh);
      r.l = down(lo, el);
      r.h = up(hi, eh);
      return;
    }
  }
  by_mpfi(r, a, nullptr, [](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr) { mpfi_sqrt(z, x); });
}

// On doubles a NaN end gives way to the other (fmin, fmax): it carries no information.
void hull(Ival& r, const Ival& a, const Ival& b) {
  if (!Ival::doubles) return mpfi_union(r.v, a.v, b.v), void();
  r.l = std::fmin(a.l, b.l);
  r.h = std::fmax(a.h, b.h);
}

void intersect(Ival& r, const Ival& a, const Ival& b) {
  if (!Ival::doubles) return mpfi_intersect(r.v, a.v, b.v), void();
  r.l = std::fmax(a.l, b.l);
  r.h = std::fmin(a.h, b.h);
}

void min(Ival& r, const Ival& a, const Ival& b) {
  if (Ival::doubles) {
    r.l = std::fmin(a.l, b.l);
    r.h = std::fmin(a.h, b.h);
  } else {
    mpfr_min(&r.v->left, &a.v->left, &b.v->left, MPFR_RNDD);
    mpfr_min(&r.v->right, &a.v->right, &b.v->right, MPFR_RNDU);
  }
}

void max(Ival& r, const Ival& a, const Ival& b) {
  if (Ival::doubles) {
    r.l = std::fmax(a.l, b.l);
    r.h = std::fmax(a.h, b.h);
  } else {
    mpfr_max(&r.v->left, &a.v->left, &b.v->left, MPFR_RNDD);
    mpfr_max(&r.v->right, &a.v->right, &b.v->right, MPFR_RNDU);
  }
}

bool one_ulp(const Ival& a) {
  if (Ival::doubles) return a.h <= next_up(a.l);
  mpfr_t t;
  mpfr_init2(t, mpfi_get_prec(a.v));
  mpfr_set(t, &a.v->left, MPFR_RNDN);
  mpfr_nextabove(t);
  const bool r = mpfr_lessequal_p(&a.v->right, t);
  mpfr_clear(t);
  return r;
}

bool is_inside(const Ival& a, const Ival& b) {
  if (Ival::doubles) return b.l <= a.l && a.h <= b.h;
  return mpfi_is_inside(a.v, b.v) > 0;
}

void mid(Ival& r, const Ival& a) {
  if (!Ival::doubles) {
    mpfi_mid(&r.v->left, a.v);
    mpfr_set(&r.v->right, &r.v->left, MPFR_RNDN);
    return;
  }
  double m = 0.5 * (a.l + a.h);
  if (!std::isfinite(m)) m = 0.5 * a.l + 0.5 * a.h;
  r.l = r.h = std::min(std::max(m, a.l), a.h);
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
  if (Ival::doubles && k == 2 && proper(a) && a.l >= 0) return sqr(r, a);  // x^2, as often
  by_mpfi(r, a, nullptr, [k](mpfi_ptr z, mpfi_srcptr x, mpfi_srcptr) {
    mpfr_pow_ui(&z->left, &x->left, k, MPFR_RNDD);
    mpfr_pow_ui(&z->right, &x->right, k, MPFR_RNDU);
  });
}

void rootn_ui(Ival& r, const Ival& a, unsigned long k) {
  if (Ival::doubles && k == 2 && proper(a) && a.l >= 0) return sqrt(r, a);
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
