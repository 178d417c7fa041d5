// Backward projections of HC4-Revise, one named kernel per operation (as ibex's bwd_mul,
// bwd_sqr), written once over the interval type I (Interval, or DInterval at 53 bits;
// the primitives are core/numerics/evaluator_ops.h). For a node r = op(a[, b]) whose value
// the pass has narrowed to [r], a kernel intersects each argument with a superset of the
// set stated in its comment, so no point satisfying the relation is removed. A kernel
// may also narrow [r] itself to op's range. Temporaries live in the caller's
// BackwardScratch: no state is kept between calls.
#pragma once

#include <cmath>

#include "numerics/arb_bounds.h"
#include "numerics/evaluator_ops.h"
#include "numerics/interval.h"

namespace aspects {

enum class Projection {
  Done,      // the arguments hold every point of the relation that they held before
  Empty,     // an argument became empty: the box holds no point of the relation
  Declined,  // doubles: a primitive declined; the caller reruns the program on MPFI
};

// Temporaries and constants of the kernels, at the working precision when created.
template <class I>
struct BackwardScratch {
  BackwardScratch() {
    Interval p;
    mpfi_const_pi(p.get());
    iops::assign(pi, p);
    mpfi_mul_2ui(p.get(), p.get(), 1);
    iops::assign(two_pi, p);
  }
  I t1, t2, t3, t4, hull;
  I pi, two_pi;   // enclosures of π and 2π
  ArbBounds arb;  // asin and acos at 53 bits
};

namespace backward_detail {

inline Projection kept_if(bool nonempty) {
  return nonempty ? Projection::Done : Projection::Empty;
}

// a ∩= hull((a ∩ p) ∪ (a ∩ −p)): the preimage of an even function (sqr, |.|, even powers)
// from its nonnegative preimage p. Uses t2, t3, t4 (p may be t1 or the node's value).
template <class I>
Projection meet_symmetric(I& a, const I& p, BackwardScratch<I>& s) {
  iops::assign(s.t2, a);
  const bool has_plus = iops::meet(s.t2, p);
  iops::neg(s.t3, p);
  iops::assign(s.t4, a);
  const bool has_minus = iops::meet(s.t4, s.t3);
  if (!has_plus && !has_minus) return Projection::Empty;
  if (has_plus && has_minus)
    iops::hull(a, s.t2, s.t4);
  else
    iops::assign(a, has_plus ? s.t2 : s.t4);
  return Projection::Done;
}

// a ∩= {t : sin t ∈ r} (or cos). The preimage is ∪k (b + 2kπ) ∪ (π − b + 2kπ) with
// b = asin(r) for sin, ∪k (±b + 2kπ) with b = acos(r) for cos; each piece is an
// enclosure, so the hull of their intersections with a contains every preimage in a.
template <class I>
Projection project_periodic(bool is_sin, I& r, I& a, BackwardScratch<I>& s) {
  iops::set_unit(s.t1);
  if (!iops::meet(r, s.t1)) return Projection::Empty;
  if (!iops::bounded(a)) return Projection::Done;
  I& base = s.t1;
  if (!iops::base_angle(is_sin, r, base, s.arb)) return Projection::Declined;
  const double period = 6.283185307179586;
  const double kmin = std::floor(iops::lo(a) / period) - 1;
  const double kmax = std::ceil(iops::hi(a) / period) + 1;
  if (kmax - kmin > 8) return Projection::Done;  // a spans many periods: nothing to gain
  const double blo = iops::lo(base), bhi = iops::hi(base);
  I& piece = s.t3;
  bool empty = true;
  for (double k = kmin; k <= kmax; ++k) {
    for (int branch = 0; branch < 2; ++branch) {
      // The piece in double, [plo, phi] up to rounding (far below the slack): a piece that
      // misses a by more than the slack misses its enclosure too, and most pieces do.
      double plo = blo, phi = bhi;
      if (branch == 1) {
        plo = (is_sin ? M_PI : 0) - bhi;
        phi = (is_sin ? M_PI : 0) - blo;
      }
      plo += period * k;
      phi += period * k;
      const double slack = 1e-9 * (1 + std::fabs(plo) + std::fabs(phi));
      if (phi + slack < iops::lo(a) || plo - slack > iops::hi(a)) continue;
      if (branch == 0)
        iops::assign(piece, base);
      else if (is_sin)
        iops::sub(piece, s.pi, base);
      else
        iops::neg(piece, base);
      iops::mul_d(s.t4, s.two_pi, k);
      iops::add(piece, piece, s.t4);
      if (!iops::meet(piece, a)) continue;
      if (empty)
        iops::assign(s.hull, piece);
      else
        iops::hull(s.hull, s.hull, piece);
      empty = false;
    }
  }
  if (empty) return Projection::Empty;
  return kept_if(iops::meet(a, s.hull));
}

}  // namespace backward_detail

// a ∩= r − b, then b ∩= r − a.                                   ({(a, b) : a + b ∈ r})
template <class I>
Projection bwd_add(const I& r, I& a, I& b, BackwardScratch<I>& s) {
  iops::sub(s.t1, r, b);
  if (!iops::meet(a, s.t1)) return Projection::Empty;
  iops::sub(s.t1, r, a);
  return backward_detail::kept_if(iops::meet(b, s.t1));
}

// a ∩= r + b, then b ∩= a − r.                                   ({(a, b) : a − b ∈ r})
template <class I>
Projection bwd_sub(const I& r, I& a, I& b, BackwardScratch<I>& s) {
  iops::add(s.t1, r, b);
  if (!iops::meet(a, s.t1)) return Projection::Empty;
  iops::sub(s.t1, a, r);
  return backward_detail::kept_if(iops::meet(b, s.t1));
}

// a ∩= r / b when 0 ∉ b, then b ∩= r / a when 0 ∉ a.            ({(a, b) : a · b ∈ r})
// (div never declines: 0 is outside the divisor.)
template <class I>
Projection bwd_mul(const I& r, I& a, I& b, BackwardScratch<I>& s) {
  if (!iops::contains_zero(b)) {
    iops::div(s.t1, r, b);
    if (!iops::meet(a, s.t1)) return Projection::Empty;
  }
  if (!iops::contains_zero(a)) {
    iops::div(s.t1, r, a);
    if (!iops::meet(b, s.t1)) return Projection::Empty;
  }
  return Projection::Done;
}

// a ∩= r · b (r bounded), then b ∩= a / r (r bounded, 0 ∉ r).   ({(a, b) : a / b ∈ r})
// a = r·b holds wherever a/b is defined (b ≠ 0).
template <class I>
Projection bwd_div(const I& r, I& a, I& b, BackwardScratch<I>& s) {
  if (iops::bounded(r)) {
    iops::mul(s.t1, r, b);
    if (!iops::meet(a, s.t1)) return Projection::Empty;
  }
  if (!iops::contains_zero(r) && iops::bounded(r)) {
    iops::div(s.t1, a, r);
    if (!iops::meet(b, s.t1)) return Projection::Empty;
  }
  return Projection::Done;
}

// a, b ∩= [lo r, +∞).                                       ({(a, b) : min(a, b) ∈ r})
template <class I>
Projection bwd_min(const I& r, I& a, I& b, BackwardScratch<I>& s) {
  iops::set_at_least(s.t1, r);
  return backward_detail::kept_if(iops::meet(a, s.t1) && iops::meet(b, s.t1));
}

// a, b ∩= (−∞, hi r].                                       ({(a, b) : max(a, b) ∈ r})
template <class I>
Projection bwd_max(const I& r, I& a, I& b, BackwardScratch<I>& s) {
  iops::set_at_most(s.t1, r);
  return backward_detail::kept_if(iops::meet(a, s.t1) && iops::meet(b, s.t1));
}

// a ∩= −r.                                                                ({a : −a ∈ r})
template <class I>
Projection bwd_neg(const I& r, I& a, BackwardScratch<I>& s) {
  iops::neg(s.t1, r);
  return backward_detail::kept_if(iops::meet(a, s.t1));
}

// r ∩= [0, +∞), a ∩= hull(a ∩ (√r ∪ −√r)).                               ({a : a² ∈ r})
template <class I>
Projection bwd_sqr(I& r, I& a, BackwardScratch<I>& s) {
  iops::set_half_line(s.t1);
  if (!iops::meet(r, s.t1)) return Projection::Empty;
  iops::sqrt(s.t1, r);
  return backward_detail::meet_symmetric(a, s.t1, s);
}

// k > 0: r ∩= [0, +∞) if k is even; a ∩= r^(1/k), or hull(a ∩ ±r^(1/k)) if k is even.
// k < 0: a unchanged (sound, weak). Not for k = 0 (the DAG has none). ({a : a^k ∈ r})
template <class I>
Projection bwd_pow(I& r, I& a, int k, BackwardScratch<I>& s) {
  if (k < 0) return Projection::Done;
  const bool even = k % 2 == 0;
  if (even) {
    iops::set_half_line(s.t1);
    if (!iops::meet(r, s.t1)) return Projection::Empty;
  }
  if (!iops::root(s.t1, r, (unsigned long)k)) return Projection::Declined;
  if (!even) return backward_detail::kept_if(iops::meet(a, s.t1));
  return backward_detail::meet_symmetric(a, s.t1, s);
}

// r ∩= [0, +∞), a ∩= r².                                                 ({a : √a ∈ r})
template <class I>
Projection bwd_sqrt(I& r, I& a, BackwardScratch<I>& s) {
  iops::set_half_line(s.t1);
  if (!iops::meet(r, s.t1)) return Projection::Empty;
  iops::sqr(s.t1, r);
  return backward_detail::kept_if(iops::meet(a, s.t1));
}

// r ∩= [0, +∞), a ∩= log r.                                          ({a : exp a ∈ r})
template <class I>
Projection bwd_exp(I& r, I& a, BackwardScratch<I>& s) {
  iops::set_half_line(s.t1);
  if (!iops::meet(r, s.t1)) return Projection::Empty;
  if (!iops::log(s.t1, r)) return Projection::Declined;
  return backward_detail::kept_if(iops::meet(a, s.t1));
}

// a ∩= exp r.                                                        ({a : log a ∈ r})
template <class I>
Projection bwd_log(const I& r, I& a, BackwardScratch<I>& s) {
  if (!iops::exp(s.t1, r)) return Projection::Declined;
  return backward_detail::kept_if(iops::meet(a, s.t1));
}

// r ∩= [0, +∞), a ∩= hull(a ∩ (r ∪ −r)).                                ({a : |a| ∈ r})
template <class I>
Projection bwd_abs(I& r, I& a, BackwardScratch<I>& s) {
  iops::set_half_line(s.t1);
  if (!iops::meet(r, s.t1)) return Projection::Empty;
  return backward_detail::meet_symmetric(a, r, s);
}

// a ∩= sin r (asin is a bijection [−1, 1] → [−π/2, π/2]).             ({a : asin a ∈ r})
template <class I>
Projection bwd_asin(const I& r, I& a, BackwardScratch<I>& s) {
  if (!iops::sin(s.t1, r)) return Projection::Declined;
  return backward_detail::kept_if(iops::meet(a, s.t1));
}

// a ∩= cos r (acos is a bijection [−1, 1] → [0, π]).                  ({a : acos a ∈ r})
template <class I>
Projection bwd_acos(const I& r, I& a, BackwardScratch<I>& s) {
  if (!iops::cos(s.t1, r)) return Projection::Declined;
  return backward_detail::kept_if(iops::meet(a, s.t1));
}

// a ∩= tan r when tan r is bounded; a unchanged otherwise.            ({a : atan a ∈ r})
template <class I>
Projection bwd_atan(const I& r, I& a, BackwardScratch<I>& s) {
  if (!iops::tan(s.t1, r)) return Projection::Declined;
  if (!iops::bounded(s.t1) || iops::is_nan(s.t1)) return Projection::Done;
  return backward_detail::kept_if(iops::meet(a, s.t1));
}

// r ∩= [−1, 1]; a ∩= hull(a ∩ ∪k (asin r + 2kπ) ∪ (π − asin r + 2kπ)); a unchanged when
// unbounded or spanning more than about 8 periods.                    ({a : sin a ∈ r})
template <class I>
Projection bwd_sin(I& r, I& a, BackwardScratch<I>& s) {
  return backward_detail::project_periodic(true, r, a, s);
}

// As bwd_sin with the pieces ±acos r + 2kπ.                            ({a : cos a ∈ r})
template <class I>
Projection bwd_cos(I& r, I& a, BackwardScratch<I>& s) {
  return backward_detail::project_periodic(false, r, a, s);
}

}  // namespace aspects
