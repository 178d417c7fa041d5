#include "model/backward.h"

#include <cmath>

#include "numerics/interval_ends.h"

namespace aspects {

using ends::L;
using ends::R;
using ends::set_half_line_pos;
using ends::set_unit;

namespace {

// acc = acc ∪ part (hull), skipping an empty part; acc_empty says acc holds nothing yet.
void hull_into(Interval& acc, bool& acc_empty, const Interval& part) {
  if (part.empty()) return;
  if (acc_empty) {
    mpfi_set(acc.get(), part.get());
    acc_empty = false;
  } else {
    mpfi_union(acc.get(), acc.get(), part.get());
  }
}

// a ∩= hull((a ∩ p) ∪ (a ∩ −p)): the preimage of an even function (sqr, |.|, even powers)
// from its nonnegative preimage p. Uses t2, t3, t4 (p may be t1 or the node's value).
bool meet_symmetric(Interval& a, const Interval& p, BackwardScratch& s) {
  mpfi_intersect(s.t2.get(), a.get(), p.get());
  mpfi_neg(s.t3.get(), p.get());
  mpfi_intersect(s.t3.get(), a.get(), s.t3.get());
  bool e = true;
  hull_into(s.t4, e, s.t2);
  hull_into(s.t4, e, s.t3);
  if (e) return false;
  mpfi_set(a.get(), s.t4.get());
  return true;
}

// base := asin(r) (sin) or acos(r) (cos), r ⊆ [−1, 1]. At 53 bits from Arb's bounds at
// the two ends (asin increases, acos decreases), otherwise MPFI.
void base_angle(bool is_sin, const Interval& r, Interval& base, BackwardScratch& s) {
  if (mpfi_get_prec(base.get()) != 53 || mpfi_get_prec(r.get()) != 53) {
    if (is_sin)
      mpfi_asin(base.get(), r.get());
    else
      mpfi_acos(base.get(), r.get());
    return;
  }
  double lo_lo, lo_hi, hi_lo, hi_hi;  // bounds of the function at r's lower and upper end
  if (is_sin) {
    s.arb.asin(r.lo_down(), lo_lo, lo_hi);
    s.arb.asin(r.hi_up(), hi_lo, hi_hi);
    mpfi_interv_d(base.get(), lo_lo, hi_hi);
  } else {
    s.arb.acos(r.lo_down(), lo_lo, lo_hi);
    s.arb.acos(r.hi_up(), hi_lo, hi_hi);
    mpfi_interv_d(base.get(), hi_lo, lo_hi);
  }
}

// a ∩= {t : sin t ∈ r} (or cos). The preimage is ∪k (b + 2kπ) ∪ (π − b + 2kπ) with
// b = asin(r) for sin, ∪k (±b + 2kπ) with b = acos(r) for cos; each piece is an MPFI
// enclosure, so the hull of their intersections with a contains every preimage in a.
bool project_periodic(bool is_sin, Interval& r, Interval& a, const Interval& two_pi,
                      BackwardScratch& s) {
  set_unit(s.t1);
  if (!r.intersect(s.t1)) return false;
  if (!a.bounded()) return true;
  Interval& base = s.t1;
  base_angle(is_sin, r, base, s);
  double period = 6.283185307179586;
  double kmin = std::floor(a.lo_down() / period) - 1, kmax = std::ceil(a.hi_up() / period) + 1;
  if (kmax - kmin > 8) return true;  // a spans many periods: nothing to gain
  const double blo = base.lo_down(), bhi = base.hi_up();
  if (is_sin) mpfi_const_pi(s.t2.get());
  Interval& piece = s.t3;
  bool empty = true;
  for (double k = kmin; k <= kmax; ++k) {
    for (int branch = 0; branch < 2; ++branch) {
      // The piece in double, [plo, phi] up to rounding (far below the slack): a piece that
      // misses a by more than the slack misses it in MPFI too, and most pieces do.
      double plo = blo, phi = bhi;
      if (branch == 1) {
        plo = (is_sin ? M_PI : 0) - bhi;
        phi = (is_sin ? M_PI : 0) - blo;
      }
      plo += period * k;
      phi += period * k;
      const double slack = 1e-9 * (1 + std::fabs(plo) + std::fabs(phi));
      if (phi + slack < a.lo_down() || plo - slack > a.hi_up()) continue;
      if (branch == 0) {
        mpfi_set(piece.get(), base.get());
      } else if (is_sin) {
        mpfi_sub(piece.get(), s.t2.get(), base.get());
      } else {
        mpfi_neg(piece.get(), base.get());
      }
      mpfi_mul_d(s.t4.get(), two_pi.get(), k);
      mpfi_add(piece.get(), piece.get(), s.t4.get());
      mpfi_intersect(piece.get(), piece.get(), a.get());
      hull_into(s.hull, empty, piece);
    }
  }
  if (empty) return false;
  return a.intersect(s.hull);
}

}  // namespace

bool bwd_add(const Interval& r, Interval& a, Interval& b, BackwardScratch& s) {
  mpfi_sub(s.t1.get(), r.get(), b.get());
  if (!a.intersect(s.t1)) return false;
  mpfi_sub(s.t1.get(), r.get(), a.get());
  return b.intersect(s.t1);
}

bool bwd_sub(const Interval& r, Interval& a, Interval& b, BackwardScratch& s) {
  mpfi_add(s.t1.get(), r.get(), b.get());
  if (!a.intersect(s.t1)) return false;
  mpfi_sub(s.t1.get(), a.get(), r.get());
  return b.intersect(s.t1);
}

bool bwd_mul(const Interval& r, Interval& a, Interval& b, BackwardScratch& s) {
  if (!b.contains_zero()) {
    mpfi_div(s.t1.get(), r.get(), b.get());
    if (!a.intersect(s.t1)) return false;
  }
  if (!a.contains_zero()) {
    mpfi_div(s.t1.get(), r.get(), a.get());
    if (!b.intersect(s.t1)) return false;
  }
  return true;
}

bool bwd_div(const Interval& r, Interval& a, Interval& b, BackwardScratch& s) {
  // a = r*b holds wherever a/b is defined (b != 0).
  if (r.bounded()) {
    mpfi_mul(s.t1.get(), r.get(), b.get());
    if (!a.intersect(s.t1)) return false;
  }
  if (!r.contains_zero() && r.bounded()) {
    mpfi_div(s.t1.get(), a.get(), r.get());
    if (!b.intersect(s.t1)) return false;
  }
  return true;
}

bool bwd_min(const Interval& r, Interval& a, Interval& b, BackwardScratch& s) {
  // min(a, b) >= lo(r) forces both >= lo(r).
  mpfr_set(L(s.t1), L(r), MPFR_RNDD);
  mpfr_set_inf(R(s.t1), 1);
  return a.intersect(s.t1) && b.intersect(s.t1);
}

bool bwd_max(const Interval& r, Interval& a, Interval& b, BackwardScratch& s) {
  mpfr_set_inf(L(s.t1), -1);
  mpfr_set(R(s.t1), R(r), MPFR_RNDU);
  return a.intersect(s.t1) && b.intersect(s.t1);
}

bool bwd_neg(const Interval& r, Interval& a, BackwardScratch& s) {
  mpfi_neg(s.t1.get(), r.get());
  return a.intersect(s.t1);
}

bool bwd_sqr(Interval& r, Interval& a, BackwardScratch& s) {
  set_half_line_pos(s.t1);
  if (!r.intersect(s.t1)) return false;
  mpfi_sqrt(s.t1.get(), r.get());  // [sqrt lo, sqrt hi]
  return meet_symmetric(a, s.t1, s);
}

bool bwd_pow(Interval& r, Interval& a, int k, BackwardScratch& s) {
  if (k < 0) return true;  // weak but sound
  unsigned long m = (unsigned long)k;
  bool even = (m % 2) == 0;
  if (even) {
    set_half_line_pos(s.t1);
    if (!r.intersect(s.t1)) return false;
  }
  mpfr_rootn_ui(L(s.t1), L(r), m, MPFR_RNDD);
  mpfr_rootn_ui(R(s.t1), R(r), m, MPFR_RNDU);
  if (!even) return a.intersect(s.t1);
  return meet_symmetric(a, s.t1, s);
}

bool bwd_sqrt(Interval& r, Interval& a, BackwardScratch& s) {
  set_half_line_pos(s.t1);
  if (!r.intersect(s.t1)) return false;
  mpfi_sqr(s.t1.get(), r.get());
  return a.intersect(s.t1);
}

bool bwd_exp(Interval& r, Interval& a, BackwardScratch& s) {
  set_half_line_pos(s.t1);
  if (!r.intersect(s.t1)) return false;
  mpfi_log(s.t1.get(), r.get());
  return a.intersect(s.t1);
}

bool bwd_log(const Interval& r, Interval& a, BackwardScratch& s) {
  mpfi_exp(s.t1.get(), r.get());
  return a.intersect(s.t1);
}

bool bwd_abs(Interval& r, Interval& a, BackwardScratch& s) {
  set_half_line_pos(s.t1);
  if (!r.intersect(s.t1)) return false;
  return meet_symmetric(a, r, s);
}

bool bwd_asin(const Interval& r, Interval& a, BackwardScratch& s) {
  mpfi_sin(s.t1.get(), r.get());
  return a.intersect(s.t1);
}

bool bwd_acos(const Interval& r, Interval& a, BackwardScratch& s) {
  mpfi_cos(s.t1.get(), r.get());
  return a.intersect(s.t1);
}

bool bwd_atan(const Interval& r, Interval& a, BackwardScratch& s) {
  mpfi_tan(s.t1.get(), r.get());
  if (!s.t1.bounded() || mpfi_nan_p(s.t1.get())) return true;
  return a.intersect(s.t1);
}

bool bwd_sin(Interval& r, Interval& a, const Interval& two_pi, BackwardScratch& s) {
  return project_periodic(true, r, a, two_pi, s);
}

bool bwd_cos(Interval& r, Interval& a, const Interval& two_pi, BackwardScratch& s) {
  return project_periodic(false, r, a, two_pi, s);
}

}  // namespace aspects
