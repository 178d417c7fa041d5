// interval_doubles.cpp — speed layer (off with --trusted-only): the operations of
// interval.h when Ival::doubles, an interval at 53 bits being two doubles. An end is the
// result rounded to nearest, moved one ulp outward exactly when an error-free
// transformation says the exact value lies on the other side: TwoSum for sums, an FMA
// residual for products, quotients and square roots. Those residuals are exact for finite
// operands unless a result is near the underflow threshold; such a case, and every
// infinite or NaN operand, is left to MPFI (a false return, or interval.cpp's by_mpfi).
// Each end is then MPFR's (test_checker_interval compares them end for end).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

#include "interval_doubles.h"

namespace cc::dbl {

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

double end(const Ival& x, End e) { return e == Lo ? x.l : x.h; }

}  // namespace

// MPFI's scratch intervals at 53 bits, per thread (interval.cpp's by_mpfi).
struct Scratch {
  mpfi_t x[3];
  Scratch() {
    for (auto& i : x) mpfi_init2(i, 53);
  }
  ~Scratch() {
    for (auto& i : x) mpfi_clear(i);
  }
};
static thread_local Scratch scratch_;

mpfi_ptr scratch(int i) { return scratch_.x[i]; }
void to_mpfi(mpfi_ptr out, const Ival& a) {
  mpfr_set_d(&out->left, a.l, MPFR_RNDD);  // exact at 53 bits, NaN included
  mpfr_set_d(&out->right, a.h, MPFR_RNDU);
}
void from_mpfi(Ival& r, mpfi_srcptr x) {
  r.l = mpfr_get_d(&x->left, MPFR_RNDD);
  r.h = mpfr_get_d(&x->right, MPFR_RNDU);
}

bool add(Ival& r, const Ival& a, const Ival& b) {
  if (!finite(a) || !finite(b)) return false;
  const double lo = a.l + b.l, hi = a.h + b.h;
  if (!std::isfinite(lo) || !std::isfinite(hi)) return false;
  const double rl = down(lo, sum_err(a.l, b.l, lo));
  r.h = up(hi, sum_err(a.h, b.h, hi));
  r.l = rl;
  return true;
}

bool sub(Ival& r, const Ival& a, const Ival& b) {
  if (!finite(a) || !finite(b)) return false;
  const double lo = a.l - b.h, hi = a.h - b.l;
  if (!std::isfinite(lo) || !std::isfinite(hi)) return false;
  const double rl = down(lo, sum_err(a.l, -b.h, lo));
  r.h = up(hi, sum_err(a.h, -b.l, hi));
  r.l = rl;
  return true;
}

// a·b from the corners the signs select (the usual nine cases): one product an end unless
// both straddle 0. Each end is the least (greatest) corner rounded down (up).
bool mul(Ival& r, const Ival& a, const Ival& b) {
  if (!proper(a) || !proper(b)) return false;
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
bool div(Ival& r, const Ival& a, const Ival& b) {
  if (!proper(a) || !proper(b) || !(b.l > 0 || b.h < 0)) return false;
  const double nl = b.l > 0 ? a.l : a.h, nh = b.l > 0 ? a.h : a.l;  // the ends' numerators
  auto op = [](double x, double y) { return x / y; };
  return ends(r, nl, nl >= 0 ? b.h : b.l, nh, nh >= 0 ? b.l : b.h, op, quotient_err);
}

bool mul_d(Ival& r, const Ival& a, double d) {  // the preconditioners' products: two corners
  auto op = [](double x, double y) { return x * y; };
  const double xl = d >= 0 ? a.l : a.h, xh = d >= 0 ? a.h : a.l;
  return proper(a) && ends(r, xl, d, xh, d, op, product_err);
}

bool sqr(Ival& r, const Ival& a) {
  if (!proper(a)) return false;
  const double m = a.l >= 0 ? a.l : a.h <= 0 ? -a.h : 0;  // the least |x|
  const double M = std::max(-a.l, a.h);                   // the largest
  const double lo = m * m, hi = M * M;
  int el = 0, eh = 0;
  if (!product_err(m, m, lo, el) || !product_err(M, M, hi, eh)) return false;
  r.l = down(lo, el);
  r.h = up(hi, eh);
  return true;
}

// sqrt(x) − s has the sign of x − s², which the FMA residual gives exactly.
bool sqrt(Ival& r, const Ival& a) {
  if (!proper(a) || a.l < 0) return false;
  if (!((a.l == 0 || a.l >= kTiny) && (a.h == 0 || a.h >= kTiny))) return false;
  auto root = [](double x, int& err) {
    const double s = std::sqrt(x);
    err = x == 0 ? 0 : sgn(std::fma(-s, s, x));
    return s;
  };
  int el = 0, eh = 0;
  const double lo = root(a.l, el), hi = root(a.h, eh);
  r.l = down(lo, el);
  r.h = up(hi, eh);
  return true;
}

bool abs(Ival& r, const Ival& a) {
  if (!proper(a)) return false;
  if (a.l >= 0) {
    r = a;
  } else if (a.h <= 0) {
    dbl::neg(r, a);
  } else {
    r.h = std::max(-a.l, a.h);
    r.l = 0;
  }
  return true;
}

void neg(Ival& r, const Ival& a) {
  const double lo = -a.h;
  r.h = -a.l;
  r.l = lo;
}

// A NaN end gives way to the other (fmin, fmax): it carries no information.
void hull(Ival& r, const Ival& a, const Ival& b) {
  r.l = std::fmin(a.l, b.l);
  r.h = std::fmax(a.h, b.h);
}
void intersect(Ival& r, const Ival& a, const Ival& b) {
  r.l = std::fmax(a.l, b.l);
  r.h = std::fmin(a.h, b.h);
}
void min(Ival& r, const Ival& a, const Ival& b) {
  r.l = std::fmin(a.l, b.l);
  r.h = std::fmin(a.h, b.h);
}
void max(Ival& r, const Ival& a, const Ival& b) {
  r.l = std::fmax(a.l, b.l);
  r.h = std::fmax(a.h, b.h);
}

void set(Ival& r, double a, double b) {
  if (b < a) std::swap(a, b);  // as mpfi_interv_d
  r.l = a;
  r.h = b;
}
bool less(const Ival& x, End ex, const Ival& y, End ey) { return end(x, ex) < end(y, ey); }
int cmp(const Ival& x, End e, double d) { return sgn(end(x, e) - d) * !std::isnan(end(x, e)); }
int end_sign(const Ival& x, End e) { return sgn(end(x, e)); }
bool one_ulp(const Ival& a) { return a.h <= next_up(a.l); }
bool is_inside(const Ival& a, const Ival& b) { return b.l <= a.l && a.h <= b.h; }

void mid(Ival& r, const Ival& a) {
  double m = 0.5 * (a.l + a.h);
  if (!std::isfinite(m)) m = 0.5 * a.l + 0.5 * a.h;
  r.l = r.h = std::min(std::max(m, a.l), a.h);
}

}  // namespace cc::dbl
