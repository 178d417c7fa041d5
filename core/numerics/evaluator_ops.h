// The primitives of the expression evaluator and of the HC4 backward kernels
// (core/model/interval_eval.h, core/model/backward.h), one overload per interval type:
// MPFI intervals at any precision, and double-ended ones at 53 bits, where each gives the
// ends MPFI gives (core/numerics/double_interval.h). The algorithms are written once over
// this set, as interval_ops.h does for the proofs' linear algebra.
//
// A primitive that returns bool, or a Restriction or Sanity, may decline on doubles: it
// then answers false (or Declined) and leaves its result unspecified, and the evaluator
// hands the whole program back to MPFI. Doubles decline what they cannot round as MPFI
// does: division by an interval holding 0, negative powers, k-th roots, every elementary
// function but sqrt, sin and cos, an argument outside sqrt's (or asin's) domain, an empty
// box, and any value that is not finite. MPFI never declines.
//
// Three-address style: the result is the first argument, and it may alias an operand.
#pragma once

#include <cmath>

#include "numerics/arb_bounds.h"
#include "numerics/double_interval.h"
#include "numerics/interval.h"
#include "numerics/interval_ends.h"
#include "numerics/interval_ops.h"

namespace aspects {
namespace iops {

// ---- Queries

inline bool empty(const Interval& x) { return x.empty(); }
inline bool empty(const DInterval& x) { return aspects::is_empty(x); }
// As empty, for a value of a forward pass: doubles decline every operation that could
// make one empty (an empty box, an argument outside a domain), so theirs never is.
inline bool may_be_empty(const Interval& x) { return x.empty(); }
inline constexpr bool may_be_empty(const DInterval&) { return false; }
inline bool bounded(const Interval& x) { return x.bounded(); }
inline bool bounded(const DInterval& x) { return aspects::is_finite(x); }
inline bool is_nan(const Interval& x) { return mpfi_nan_p(x.get()); }
inline bool is_nan(const DInterval& x) { return std::isnan(x.lo) || std::isnan(x.hi); }
// The same ends (a zero equals a zero of either sign).
inline bool same_ends(const Interval& x, const Interval& y) {
  return mpfr_equal_p(ends::L(x), ends::L(y)) && mpfr_equal_p(ends::R(x), ends::R(y));
}
inline bool same_ends(const DInterval& x, const DInterval& y) { return aspects::same(x, y); }
// Both ends are zero.
inline bool is_zero(const Interval& x) {
  return mpfr_zero_p(ends::L(x)) && mpfr_zero_p(ends::R(x));
}
inline bool is_zero(const DInterval& x) { return x.lo == 0 && x.hi == 0; }
// +1 or −1 when every point of x has that sign, 0 otherwise.
inline int sign_of(const Interval& x) { return certain_sign(x); }
inline int sign_of(const DInterval& x) { return x.lo > 0 ? 1 : x.hi < 0 ? -1 : 0; }
// Every point of a lies below (above) every point of b.
inline bool certainly_below(const Interval& a, const Interval& b) {
  return mpfr_less_p(ends::R(a), ends::L(b));
}
inline bool certainly_below(const DInterval& a, const DInterval& b) { return a.hi < b.lo; }
inline bool certainly_above(const Interval& a, const Interval& b) {
  return mpfr_greater_p(ends::L(a), ends::R(b));
}
inline bool certainly_above(const DInterval& a, const DInterval& b) { return a.lo > b.hi; }

// ---- Constants and copies

inline void assign(DInterval& r, const DInterval& x) { r = x; }
inline void set_int(Interval& r, long v) { mpfi_set_si(r.get(), v); }
inline void set_int(DInterval& r, long v) { r = {double(v), double(v)}; }
inline void set_int_range(Interval& r, long lo, long hi) { mpfi_interv_si(r.get(), lo, hi); }
inline void set_int_range(DInterval& r, long lo, long hi) { r = {double(lo), double(hi)}; }
inline void set_unit(Interval& r) { ends::set_unit(r); }  // [−1, 1]
inline void set_unit(DInterval& r) { r = {-1, 1}; }
inline void set_half_line(Interval& r) { ends::set_half_line_pos(r); }  // [0, +∞]
inline void set_half_line(DInterval& r) { r = {0.0, INFINITY}; }
// r = [lo x, +∞] and r = [−∞, hi x].
inline void set_at_least(Interval& r, const Interval& x) {
  mpfr_set(ends::L(r), ends::L(x), MPFR_RNDD);
  mpfr_set_inf(ends::R(r), 1);
}
inline void set_at_least(DInterval& r, const DInterval& x) { r = {x.lo, INFINITY}; }
inline void set_at_most(Interval& r, const Interval& x) {
  mpfr_set_inf(ends::L(r), -1);
  mpfr_set(ends::R(r), ends::R(x), MPFR_RNDU);
}
inline void set_at_most(DInterval& r, const DInterval& x) { r = {-INFINITY, x.hi}; }
// r = [lo x, lo x] and r = [hi x, hi x]: the ends as points.
inline void set_lower_end(Interval& r, const Interval& x) { mpfi_set_fr(r.get(), ends::L(x)); }
inline void set_lower_end(DInterval& r, const DInterval& x) { r = {x.lo, x.lo}; }
inline void set_upper_end(Interval& r, const Interval& x) { mpfi_set_fr(r.get(), ends::R(x)); }
inline void set_upper_end(DInterval& r, const DInterval& x) { r = {x.hi, x.hi}; }

// A box's variable as the evaluator reads it; false (declined) for an empty one on doubles.
inline bool load(Interval& r, const Interval& x) {
  mpfi_set(r.get(), x.get());
  return true;
}
inline bool load(DInterval& r, const Interval& x) {
  r = to_dinterval(x);
  return !aspects::is_empty(r);
}
// Writes a variable's HC4 value v ⊆ x back into the box variable x, read as `read`.
// MPFI intersects, as every kernel does; doubles write only a change, exactly (53 bits),
// so that an untouched variable keeps its own ends.
inline void store_narrowed(Interval& x, const Interval& v, const Interval&) { x.intersect(v); }
inline void store_narrowed(Interval& x, const DInterval& v, const DInterval& read) {
  if (!aspects::same(v, read)) x.set_hull(v.lo, v.hi);
}

// ---- Arithmetic (outward rounded)

inline void add(Interval& r, const Interval& a, const Interval& b) {
  mpfi_add(r.get(), a.get(), b.get());
}
inline void add(DInterval& r, const DInterval& a, const DInterval& b) { r = aspects::add(a, b); }
inline void sub(Interval& r, const Interval& a, const Interval& b) {
  mpfi_sub(r.get(), a.get(), b.get());
}
inline void sub(DInterval& r, const DInterval& a, const DInterval& b) { r = aspects::sub(a, b); }
inline void mul(Interval& r, const Interval& a, const Interval& b) {
  mpfi_mul(r.get(), a.get(), b.get());
}
inline void mul(DInterval& r, const DInterval& a, const DInterval& b) { r = aspects::mul(a, b); }
inline void sqr(Interval& r, const Interval& a) { mpfi_sqr(r.get(), a.get()); }
inline void sqr(DInterval& r, const DInterval& a) { r = aspects::sqr(a); }
inline void neg(Interval& r, const Interval& a) { mpfi_neg(r.get(), a.get()); }
inline void neg(DInterval& r, const DInterval& a) { r = aspects::neg(a); }
inline void abs(Interval& r, const Interval& a) { mpfi_abs(r.get(), a.get()); }
inline void abs(DInterval& r, const DInterval& a) {
  if (a.lo >= 0)
    r = a;
  else if (a.hi <= 0)
    r = aspects::neg(a);
  else
    r = {0.0, std::max(-a.lo, a.hi)};
}
// 0 ≤ lo a.
inline void sqrt(Interval& r, const Interval& a) { mpfi_sqrt(r.get(), a.get()); }
inline void sqrt(DInterval& r, const DInterval& a) { r = aspects::sqrt(a); }
// r = a / b; doubles decline when 0 ∈ b (never otherwise).
inline bool div(Interval& r, const Interval& a, const Interval& b) {
  mpfi_div(r.get(), a.get(), b.get());
  return true;
}
inline bool div(DInterval& r, const DInterval& a, const DInterval& b) {
  if (has_zero(b)) return false;
  r = aspects::div(a, b);
  return true;
}
// r = 1 / a; doubles decline.
inline bool inv(Interval& r, const Interval& a) {
  mpfi_inv(r.get(), a.get());
  return true;
}
inline bool inv(DInterval&, const DInterval&) { return false; }
// The ends' minimum and maximum, exact.
inline void min_of(Interval& r, const Interval& a, const Interval& b) {
  mpfr_min(ends::L(r), ends::L(a), ends::L(b), MPFR_RNDD);
  mpfr_min(ends::R(r), ends::R(a), ends::R(b), MPFR_RNDU);
}
inline void min_of(DInterval& r, const DInterval& a, const DInterval& b) {
  r = {std::min(a.lo, b.lo), std::min(a.hi, b.hi)};
}
inline void max_of(Interval& r, const Interval& a, const Interval& b) {
  mpfr_max(ends::L(r), ends::L(a), ends::L(b), MPFR_RNDD);
  mpfr_max(ends::R(r), ends::R(a), ends::R(b), MPFR_RNDU);
}
inline void max_of(DInterval& r, const DInterval& a, const DInterval& b) {
  r = {std::max(a.lo, b.lo), std::max(a.hi, b.hi)};
}
// r = a ∪ b (the hull).
inline void hull(Interval& r, const Interval& a, const Interval& b) {
  mpfi_union(r.get(), a.get(), b.get());
}
inline void hull(DInterval& r, const DInterval& a, const DInterval& b) { r = aspects::hull(a, b); }
// x = x ∩ y; false when empty.
inline bool meet(Interval& x, const Interval& y) { return x.intersect(y); }
inline bool meet(DInterval& x, const DInterval& y) { return aspects::meet(x, y); }

// ---- Elementary functions: MPFI's; doubles decline (sin and cos go through SinCos)

inline bool exp(Interval& r, const Interval& a) { return mpfi_exp(r.get(), a.get()), true; }
inline bool exp(DInterval&, const DInterval&) { return false; }
inline bool log(Interval& r, const Interval& a) { return mpfi_log(r.get(), a.get()), true; }
inline bool log(DInterval&, const DInterval&) { return false; }
inline bool tan(Interval& r, const Interval& a) { return mpfi_tan(r.get(), a.get()), true; }
inline bool tan(DInterval&, const DInterval&) { return false; }
inline bool atan(Interval& r, const Interval& a) { return mpfi_atan(r.get(), a.get()), true; }
inline bool atan(DInterval&, const DInterval&) { return false; }
inline bool asin(Interval& r, const Interval& a) { return mpfi_asin(r.get(), a.get()), true; }
inline bool asin(DInterval&, const DInterval&) { return false; }
inline bool acos(Interval& r, const Interval& a) { return mpfi_acos(r.get(), a.get()), true; }
inline bool acos(DInterval&, const DInterval&) { return false; }
// MPFI's own sin and cos of one interval (the backward kernels of asin and acos).
inline bool sin(Interval& r, const Interval& a) { return mpfi_sin(r.get(), a.get()), true; }
inline bool sin(DInterval&, const DInterval&) { return false; }
inline bool cos(Interval& r, const Interval& a) { return mpfi_cos(r.get(), a.get()), true; }
inline bool cos(DInterval&, const DInterval&) { return false; }
// r ⊇ a^(1/k), k > 0, each end rounded outward; doubles decline.
inline bool root(Interval& r, const Interval& a, unsigned long k) {
  mpfr_rootn_ui(ends::L(r), ends::L(a), k, MPFR_RNDD);
  mpfr_rootn_ui(ends::R(r), ends::R(a), k, MPFR_RNDU);
  return true;
}
inline bool root(DInterval&, const DInterval&, unsigned long) { return false; }

// base ⊇ asin(r) (is_sin) or acos(r), r ⊆ [−1, 1]. At 53 bits from Arb's bounds at the two
// ends (asin increases, acos decreases); above, MPFI's. Doubles decline a bound Arb does
// not give.
inline bool base_angle(bool is_sin, const Interval& r, Interval& base, ArbBounds& arb) {
  if (mpfi_get_prec(base.get()) != 53 || mpfi_get_prec(r.get()) != 53) {
    if (is_sin)
      mpfi_asin(base.get(), r.get());
    else
      mpfi_acos(base.get(), r.get());
    return true;
  }
  double lo_lo, lo_hi, hi_lo, hi_hi;  // bounds of the function at r's lower and upper end
  if (is_sin) {
    arb.asin(r.lo_down(), lo_lo, lo_hi);
    arb.asin(r.hi_up(), hi_lo, hi_hi);
    mpfi_interv_d(base.get(), lo_lo, hi_hi);
  } else {
    arb.acos(r.lo_down(), lo_lo, lo_hi);
    arb.acos(r.hi_up(), hi_lo, hi_hi);
    mpfi_interv_d(base.get(), hi_lo, lo_hi);
  }
  return true;
}
inline bool base_angle(bool is_sin, const DInterval& r, DInterval& base, ArbBounds& arb) {
  double lo_lo, lo_hi, hi_lo, hi_hi;
  if (is_sin) {
    arb.asin(r.lo, lo_lo, lo_hi);
    arb.asin(r.hi, hi_lo, hi_hi);
    base = {lo_lo, hi_hi};
  } else {
    arb.acos(r.lo, lo_lo, lo_hi);
    arb.acos(r.hi, hi_lo, hi_hi);
    base = {hi_lo, lo_hi};
  }
  return aspects::is_finite(base);
}

// ---- Domains and values the evaluator checks

enum class Restriction {
  Whole,     // x ⊆ domain: out = x
  Part,      // out = x ∩ domain, possibly empty: the function is undefined somewhere in x
  Declined,  // doubles: x leaves the domain
};
inline Restriction restrict_to(Interval& out, const Interval& x, const Interval& domain) {
  mpfi_intersect(out.get(), x.get(), domain.get());
  return mpfi_is_inside(x.get(), domain.get()) > 0 ? Restriction::Whole : Restriction::Part;
}
inline Restriction restrict_to(DInterval& out, const DInterval& x, const DInterval& domain) {
  if (!(domain.lo <= x.lo && x.hi <= domain.hi)) return Restriction::Declined;
  out = x;
  return Restriction::Whole;
}

enum class Sanity {
  Kept,        // r is a valid enclosure as computed
  MadeEntire,  // MPFI: r was NaN (a case the domain checks should exclude); now (−∞, +∞)
  Declined,    // doubles: r is not finite
};
inline Sanity sanitize(Interval& r) {
  if (!mpfi_nan_p(r.get())) return Sanity::Kept;
  r.set_entire();
  return Sanity::MadeEntire;
}
inline Sanity sanitize(DInterval& r) {
  return aspects::is_finite(r) ? Sanity::Kept : Sanity::Declined;
}

}  // namespace iops
}  // namespace aspects
