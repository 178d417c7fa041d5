// The few interval operations the proofs' linear algebra needs (proofs/preconditioner.*,
// proofs/hansen_sengupta.cpp), in one overload set for MPFI
// intervals and for double-ended ones, so that each algorithm is written once and runs
// on doubles at 53 bits, where both give the same ends (core/numerics/double_interval.h).
// Three-address style, as MPFI: the result is the first argument.
#pragma once

#include "numerics/double_interval.h"
#include "numerics/interval.h"

namespace aspects {
namespace iops {

inline void assign(Interval& r, const Interval& x) { mpfi_set(r.get(), x.get()); }
inline void assign(DInterval& r, const Interval& x) { r = to_dinterval(x); }
inline void store(Interval& r, const Interval& x) { mpfi_set(r.get(), x.get()); }
inline void store(Interval& r, const DInterval& x) { r.set_hull(x.lo, x.hi); }  // exact
inline void set_zero(Interval& r) { mpfi_set_si(r.get(), 0); }
inline void set_zero(DInterval& r) { r = {0, 0}; }

inline void add_to(Interval& r, const Interval& a) { mpfi_add(r.get(), r.get(), a.get()); }
inline void add_to(DInterval& r, const DInterval& a) { r = add(r, a); }
inline void mul_into(Interval& r, const Interval& a) { mpfi_mul(r.get(), r.get(), a.get()); }
inline void mul_into(DInterval& r, const DInterval& a) { r = mul(r, a); }
inline void div_into(Interval& r, const Interval& a) { mpfi_div(r.get(), r.get(), a.get()); }
inline void div_into(DInterval& r, const DInterval& a) { r = div(r, a); }
// r = a·c
inline void mul_d(Interval& r, const Interval& a, double c) { mpfi_mul_d(r.get(), a.get(), c); }
inline void mul_d(DInterval& r, const DInterval& a, double c) { r = mul(a, {c, c}); }
// r = r − c
inline void sub_d(Interval& r, double c) { mpfi_sub_d(r.get(), r.get(), c); }
inline void sub_d(DInterval& r, double c) { r = sub(r, {c, c}); }
// r = c − a
inline void d_sub(Interval& r, double c, const Interval& a) { mpfi_d_sub(r.get(), c, a.get()); }
inline void d_sub(DInterval& r, double c, const DInterval& a) { r = sub({c, c}, a); }
// r = a ∩ b; false when empty
inline bool meet_of(Interval& r, const Interval& a, const Interval& b) {
  mpfi_intersect(r.get(), a.get(), b.get());
  return !r.empty();
}
inline bool meet_of(DInterval& r, const DInterval& a, const DInterval& b) {
  r = a;
  return meet(r, b);
}

inline bool contains_zero(const Interval& x) { return x.contains_zero(); }
inline bool contains_zero(const DInterval& x) { return has_zero(x); }
inline bool usable(const Interval& x) { return x.bounded() && !x.empty(); }  // bounded, nonempty
inline bool usable(const DInterval& x) { return is_finite(x) && !is_empty(x); }
inline double lo(const Interval& x) { return x.lo_down(); }
inline double lo(const DInterval& x) { return x.lo; }
inline double hi(const Interval& x) { return x.hi_up(); }
inline double hi(const DInterval& x) { return x.hi; }
inline double mid(const Interval& x) { return x.mid(); }
inline double mid(const DInterval& x) { return aspects::mid(x); }
inline double width(const Interval& x) { return x.width_up(); }
inline double width(const DInterval& x) { return width_up(x); }

}  // namespace iops
}  // namespace aspects
