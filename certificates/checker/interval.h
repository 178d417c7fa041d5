// interval.h — the checker's only interval type. Trusted core: MPFI at the certificate's
// precision (interval.cpp). Speed layer (off with --trusted-only): at 53 bits, the solver's
// default, an interval is two doubles, and sums, products, quotients and square roots are
// computed in binary64 with each end rounded as MPFR rounds it (lo down, hi up), the
// direction recovered exactly by an error-free transformation (interval_doubles.cpp); every
// other function, and every case the transformation does not cover (infinite or NaN ends,
// results near the underflow threshold), goes to MPFI on the same ends and is rounded
// outward to doubles. Each result encloses the exact one, and is MPFI's end for end wherever
// MPFR's is a double (test_checker_interval compares them; the corpus and tamper tests
// compare the verdicts).
#pragma once

#include <mpfi.h>

#include <cmath>
#include <string>

namespace cc {

// Sets the precision of every interval (MPFR's default precision too), and whether 53 bits
// are held as doubles. Called before any Ival exists, and not again while one does.
void set_interval_precision(mpfr_prec_t bits, bool doubles);

enum End { Lo, Hi };

class Ival {
 public:
  Ival();  // NaN ends, as MPFI initialises them
  Ival(const Ival& o);
  Ival& operator=(const Ival& o) {  // inline: the evaluator copies a value per node
    if (doubles) l = o.l, h = o.h;
    else if (this != &o) mpfi_set(v, o.v);
    return *this;
  }
  ~Ival();

  // The ends as doubles rounded outward (lo down, hi up); exact at 53 bits.
  double lo() const { return doubles ? l : mpfr_get_d(&v->left, MPFR_RNDD); }
  double hi() const { return doubles ? h : mpfr_get_d(&v->right, MPFR_RNDU); }
  void set(double lo, double hi);  // [lo, hi], exact doubles
  void set_end(End e, double x);   // one end := x
  void entire();
  bool nan() const { return doubles ? std::isnan(l) || std::isnan(h) : mpfi_nan_p(v); }
  bool empty() const { return doubles ? !(l <= h) : mpfi_nan_p(v) || mpfi_is_empty(v); }
  bool bounded() const {  // neither NaN nor infinite
    return doubles ? std::isfinite(l) && std::isfinite(h) : !mpfi_nan_p(v) && mpfi_bounded_p(v);
  }
  bool has_zero() const { return doubles ? l <= 0 && 0 <= h : mpfi_has_zero(v) > 0; }
  bool is_zero() const;  // [0, 0]
  int sign() const;      // +1 when lo > 0, -1 when hi < 0, else 0 (also when empty)
  int end_sign(End e) const;  // the sign of one end (0 when NaN)
  bool meet(const Ival& o);   // this ∩= o; false when the result is empty

  static bool doubles;  // 53 bits: the double representation
  mpfi_t v;             // the MPFI representation (initialised only when !doubles)
  double l = 0, h = 0;  // the double representation
};

// Exact comparisons of ends; false when either is NaN.
bool less(const Ival& x, End ex, const Ival& y, End ey);
inline bool same(const Ival& x, End ex, const Ival& y, End ey) {  // inline: the caches' test
  if (Ival::doubles) return (ex == Lo ? x.l : x.h) == (ey == Lo ? y.l : y.h);
  return mpfr_equal_p(ex == Lo ? &x.v->left : &x.v->right, ey == Lo ? &y.v->left : &y.v->right);
}
int cmp(const Ival& x, End e, double d);  // as mpfr_cmp_d: 0 when NaN
// dst's end ed := src's end es, exactly; point: both ends of dst := src's end es.
void copy_end(Ival& dst, End ed, const Ival& src, End es);
void point(Ival& dst, const Ival& src, End es);
// The ends as an exact mpfr number of the interval's precision (Arb's input), and back:
// an end := the given value rounded outward (down for Lo, up for Hi).
void get_end(mpfr_ptr out, const Ival& x, End e);
void set_end(Ival& x, End e, mpfr_srcptr value);

// The operations, r := f(a, b), outward rounded (MPFI's semantics for NaN and infinities).
void set_si(Ival& r, long k);
void add(Ival& r, const Ival& a, const Ival& b);
void sub(Ival& r, const Ival& a, const Ival& b);
void mul(Ival& r, const Ival& a, const Ival& b);
void div(Ival& r, const Ival& a, const Ival& b);
void add_d(Ival& r, const Ival& a, double d);
void mul_d(Ival& r, const Ival& a, double d);
void si_sub(Ival& r, long k, const Ival& a);
void neg(Ival& r, const Ival& a);
void abs(Ival& r, const Ival& a);
void sqr(Ival& r, const Ival& a);
void inv(Ival& r, const Ival& a);
void sqrt(Ival& r, const Ival& a);
void hull(Ival& r, const Ival& a, const Ival& b);
void intersect(Ival& r, const Ival& a, const Ival& b);
bool is_inside(const Ival& a, const Ival& b);  // a ⊆ b (false when either is NaN)
bool one_ulp(const Ival& a);                   // hi is at most the successor of lo
void mid(Ival& r, const Ival& a);              // a point of a, near its middle
void min(Ival& r, const Ival& a, const Ival& b);
void max(Ival& r, const Ival& a, const Ival& b);
// Through MPFI at every precision:
enum class Fn { Exp, Log, Sin, Cos, Tan, Asin, Acos, Atan };
void apply_fn(Fn f, Ival& r, const Ival& a);
void pow_ui(Ival& r, const Ival& a, unsigned long k);  // a^k by ends: a monotone (a >= 0 or k odd)
void rootn_ui(Ival& r, const Ival& a, unsigned long k);  // k-th root by ends
void log_hi(Ival& r, const Ival& a);  // [-inf, log(a.hi) rounded up]
void const_pi(Ival& r);
bool set_str(Ival& r, const std::string& decimal);  // false: not a number

}  // namespace cc
