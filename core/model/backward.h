// Backward projections of HC4-Revise, one named kernel per operation (as ibex's bwd_mul,
// bwd_sqr). For a node r = op(a[, b]) whose value the pass has narrowed to [r], a kernel
// intersects each argument with a superset of the set stated in its comment, so no point
// satisfying the relation is removed. Each returns false when an argument became empty
// (the box holds no such point). A kernel may also narrow [r] itself to op's range.
// Temporaries live in the caller's BackwardScratch: no state is kept between calls.
#pragma once

#include "numerics/arb_bounds.h"
#include "numerics/interval.h"

namespace aspects {

// Temporaries of the kernels, at the working precision when created. One per evaluator.
struct BackwardScratch {
  Interval t1, t2, t3, t4, hull;
  ArbBounds arb;  // asin and acos at 53 bits
};

// a ∩= r − b, then b ∩= r − a.                                   ({(a, b) : a + b ∈ r})
bool bwd_add(const Interval& r, Interval& a, Interval& b, BackwardScratch& s);
// a ∩= r + b, then b ∩= a − r.                                   ({(a, b) : a − b ∈ r})
bool bwd_sub(const Interval& r, Interval& a, Interval& b, BackwardScratch& s);
// a ∩= r / b when 0 ∉ b, then b ∩= r / a when 0 ∉ a.            ({(a, b) : a · b ∈ r})
bool bwd_mul(const Interval& r, Interval& a, Interval& b, BackwardScratch& s);
// a ∩= r · b (r bounded), then b ∩= a / r (r bounded, 0 ∉ r).   ({(a, b) : a / b ∈ r})
bool bwd_div(const Interval& r, Interval& a, Interval& b, BackwardScratch& s);
// a, b ∩= [lo r, +∞).                                       ({(a, b) : min(a, b) ∈ r})
bool bwd_min(const Interval& r, Interval& a, Interval& b, BackwardScratch& s);
// a, b ∩= (−∞, hi r].                                       ({(a, b) : max(a, b) ∈ r})
bool bwd_max(const Interval& r, Interval& a, Interval& b, BackwardScratch& s);
// a ∩= −r.                                                                ({a : −a ∈ r})
bool bwd_neg(const Interval& r, Interval& a, BackwardScratch& s);
// r ∩= [0, +∞), a ∩= hull(a ∩ (√r ∪ −√r)).                               ({a : a² ∈ r})
bool bwd_sqr(Interval& r, Interval& a, BackwardScratch& s);
// k > 0: r ∩= [0, +∞) if k is even; a ∩= r^(1/k), or hull(a ∩ ±r^(1/k)) if k is even.
// k < 0: a unchanged (sound, weak). Not for k = 0 (the DAG has none). ({a : a^k ∈ r})
bool bwd_pow(Interval& r, Interval& a, int k, BackwardScratch& s);
// r ∩= [0, +∞), a ∩= r².                                                 ({a : √a ∈ r})
bool bwd_sqrt(Interval& r, Interval& a, BackwardScratch& s);
// r ∩= [0, +∞), a ∩= log r.                                          ({a : exp a ∈ r})
bool bwd_exp(Interval& r, Interval& a, BackwardScratch& s);
// a ∩= exp r.                                                        ({a : log a ∈ r})
bool bwd_log(const Interval& r, Interval& a, BackwardScratch& s);
// r ∩= [0, +∞), a ∩= hull(a ∩ (r ∪ −r)).                                ({a : |a| ∈ r})
bool bwd_abs(Interval& r, Interval& a, BackwardScratch& s);
// a ∩= sin r (asin is a bijection [−1, 1] → [−π/2, π/2]).             ({a : asin a ∈ r})
bool bwd_asin(const Interval& r, Interval& a, BackwardScratch& s);
// a ∩= cos r (acos is a bijection [−1, 1] → [0, π]).                  ({a : acos a ∈ r})
bool bwd_acos(const Interval& r, Interval& a, BackwardScratch& s);
// a ∩= tan r when tan r is bounded; a unchanged otherwise.            ({a : atan a ∈ r})
bool bwd_atan(const Interval& r, Interval& a, BackwardScratch& s);
// r ∩= [−1, 1]; a ∩= hull(a ∩ ∪k (asin r + 2kπ) ∪ (π − asin r + 2kπ)); a unchanged when
// unbounded or spanning more than about 8 periods.                    ({a : sin a ∈ r})
bool bwd_sin(Interval& r, Interval& a, const Interval& two_pi, BackwardScratch& s);
// As bwd_sin with the pieces ±acos r + 2kπ.                            ({a : cos a ∈ r})
bool bwd_cos(Interval& r, Interval& a, const Interval& two_pi, BackwardScratch& s);

}  // namespace aspects
