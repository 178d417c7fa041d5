// The star-shaped test of Delanoue, Jaulin and Cottenceau ("Using interval arithmetic to
// prove that a set is path-connected", TCS 2006), on a piece given in a chart by
//   S = {u ∈ U : φ_i(u) > 0 for the strict constraints, ψ_j(u) ≥ 0 for the closed ones}:
//  - strict: a factor, φ = s_i·g_i(u, w(u));
//  - closed: a face of the box's W, ψ = w_j(u) − lo_j or hi_j − w_j(u): where the graph
//    leaves the box, the piece is the graph over {u : w(u) ∈ W};
//  - a constraint's atom left Unknown on the box (counting/constraint_reduction.h),
//    a(u) = g(u, w(u)): strict (g > 0) like a factor, closed (g ≥ 0) like a face. The proof
//    below uses only that every constraint is continuous on U and differentiable where its
//    gradient is enclosed, which holds for an atom whose expression is defined on U × the
//    range of w (checked before the test) and differentiable where its derivatives are.
// S is star-shaped about v (every constraint > 0 at v) when no u ∈ U has every constraint
// ≥ 0 and either (i) a strict φ_i(u) = 0 with ∇φ_i(u)·(u − v) ≥ 0, or (ii) every strict
// φ > 0 and a closed ψ_j(u) = 0 with ∇ψ_j(u)·(u − v) ≥ 0.
// Proof: if the segment from v to a u ∈ S leaves S, let t1 > 0 be the least t with the
// segment in S on (t, 1], and p1 its point there (p1 ∈ U, convex). By continuity every
// constraint is ≥ 0 at p1. If p1 ∉ S, a strict φ_i(p1) = 0 with φ_i > 0 after t1: its
// derivative along the segment is ≥ 0, and (p1 − v) = t1(u − v): case (i). If p1 ∈ S, every
// φ > 0 there, so some ψ_j(p1) = 0 is what fails before t1, with ψ_j ≥ 0 after: case (ii).
// The test paves U: a sub-box is cleared when a constraint is certainly < 0 on it, or when
// each constraint that (i) or (ii) needs is certainly ≠ 0 there or has ∇·(S − v) certainly
// < 0 (the implicit gradient of factor_gradients.h, which proves ∂_w f regular where it is
// used); otherwise it is bisected, down to a least width.
#pragma once

#include <cstdint>
#include <vector>

#include "counting/factor_gradients.h"

namespace aspects {

enum class StarVerdict : uint8_t {
  StarShaped,  // proved
  NotProved,   // ψ(v) > 0 not proved, or a sub-box could not be cleared above the least
               // width, or the budget ran out
};

struct StarConstraint {
  enum Kind : uint8_t { Factor, WLower, WUpper, AtomStrict, AtomClosed } kind = Factor;
  int index = 0;   // Factor: the factor; WLower/WUpper: j, the chart's w_j; Atom*: the atom
                   // (an index into model.constraint_atoms and the atoms' FactorGradients)
  int sign = 1;    // Factor: s_i (strict); the faces are closed
  double bound = 0;  // WLower/WUpper: lo_j or hi_j
};

struct StarLimits {
  double min_width = 1e-6;  // relative to the box's width
  // Past it the box is bisected instead (a smaller box is easier). Near a crossing of two
  // singular curves the pieces are thin wedges: 2000 left RRRRR's count open there.
  long max_boxes = 8000;  // check_cert allows more (its arithmetic is not this one)
};

// `box`: U × the chart's range of w (every w(u) lies in it). v: the centre's u (n doubles),
// wv: an enclosure of w(v). `boxes` counts the paving. `atoms`: the gradients of the
// constraints' atoms (needed when cs holds an Atom constraint).
StarVerdict star_test(ModelEvaluator& ev, const FactorGradients& fg, const Chart& chart,
                      const Box& box, const std::vector<StarConstraint>& cs,
                      const std::vector<double>& v,
                      const std::vector<Interval>& wv, const StarLimits& limits, HsWorkspace& ws,
                      long& boxes, const FactorGradients* atoms = nullptr);

inline bool strict_constraint(const StarConstraint& c) {
  return c.kind == StarConstraint::Factor || c.kind == StarConstraint::AtomStrict;
}

}  // namespace aspects
