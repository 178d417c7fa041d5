// interval_doubles.h — speed layer (off with --trusted-only): the operations of interval.h
// when Ival::doubles, defined in interval_doubles.cpp and called by interval.cpp. Those
// returning bool compute finite proper operands away from the underflow threshold; false
// leaves the case to MPFI. MPFI on doubles: per-thread 53-bit scratch intervals (0..2), and
// the exact conversions to them and back (outward).
#pragma once

#include "interval.h"

namespace cc::dbl {

bool add(Ival& r, const Ival& a, const Ival& b);
bool sub(Ival& r, const Ival& a, const Ival& b);
bool mul(Ival& r, const Ival& a, const Ival& b);
bool div(Ival& r, const Ival& a, const Ival& b);
bool mul_d(Ival& r, const Ival& a, double d);
bool sqr(Ival& r, const Ival& a);
bool sqrt(Ival& r, const Ival& a);
bool abs(Ival& r, const Ival& a);
void neg(Ival& r, const Ival& a);
void hull(Ival& r, const Ival& a, const Ival& b);
void intersect(Ival& r, const Ival& a, const Ival& b);
void min(Ival& r, const Ival& a, const Ival& b);
void max(Ival& r, const Ival& a, const Ival& b);
void set(Ival& r, double lo, double hi);
bool less(const Ival& x, End ex, const Ival& y, End ey);
int cmp(const Ival& x, End e, double d);
int end_sign(const Ival& x, End e);
bool one_ulp(const Ival& a);
bool is_inside(const Ival& a, const Ival& b);
void mid(Ival& r, const Ival& a);
mpfi_ptr scratch(int i);
void to_mpfi(mpfi_ptr out, const Ival& a);
void from_mpfi(Ival& r, mpfi_srcptr x);

}  // namespace cc::dbl
