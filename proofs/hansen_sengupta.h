// Property P1 (paper 4.2.1, existence proof): the parametric Hansen–Sengupta operator
// on f([x], q) = 0, with the pose [x] as interval parameter and the command q unknown.
//
// H([x],[q]) = mid[q] − GS(C·Fq([x],[q]), C·f([x], mid[q])) (interval Gauss–Seidel)
// with C ≈ mid(Fq)^-1 chosen in double. If ∅ ≠ H([x],[q̃]) ⊆ int [q̃] then
//   ∀x ∈ [x], ∃! q ∈ [q̃] with f(x, q) = 0, and that q lies in H([x],[q̃]).
// prove_existence runs iteration (9): inflate by τ, apply H without intersecting, and
// stop at the first strict inclusion.
#pragma once

#include <vector>

#include "numerics/interval.h"
#include "model/model_eval.h"

namespace aspects {

enum class HsStatus {
  Ok,        // image computed
  NoSolution,  // (with intersection) the box holds no zero of f(x,·) for any x ∈ [x]
  Failed,    // operator not applicable: f undefined somewhere, (C·Fq)_ii ∋ 0, singular mid
};

// The arrays of one sweep, with MPFI ends or with double ends.
template <class I>
struct HsArrays {
  std::vector<I> f0, b, q, y;  // q: the unknowns' box, y: their image
  Matrix<I> J, A;
  Matrix<I> Jx, Jq;  // a chart of mixed unknowns: both Jacobians, J from their columns
  Matrix<I> Jp;      // and the parameters' columns, for the centred f(U, w̌)
  std::vector<I> fc;
  I t1, t2;
};

// At a working precision of 53 bits the sweep runs on doubles (the same ends as MPFI,
// core/numerics/interval_ops.h); otherwise on MPFI.
struct HsWorkspace {
  HsArrays<Interval> mpfi;
  HsArrays<DInterval> doubles;
  bool in_doubles = false;  // the arrays the last sweep filled
  std::vector<double> C;
  Box mid_box;
};

// One Hansen–Sengupta sweep on the command part of `box` (model order). The image of
// command j is written to image[j]. With `intersect`, each component is intersected
// with the box (the contracting operator used by Prune). C is left in ws.C.
// With `in_pose` the roles swap: the pose is unknown, the commands are the parameters and
// Fx replaces Fq (the existence proof in x of cuspidality witnesses, core/aspects/cuspidality.h).
// With `unknowns` (n variable indices, model order), those are the unknowns and the others
// the parameters, whatever their kind (a chart of the counting, proofs/counting/chart.h),
// and f(U, w̌) is also enclosed in the centred form f(ǔ, w̌) + ∂_u f(box)·(U − ǔ) (mean
// value theorem, ǔ the parameters' midpoint), then met with the natural one: a chart's U is
// wide and the natural form of, say, (x − 8 cos q)² + (y − 8 sin q)² loses the tie between
// cos and sin. (The solve's P1 keeps the natural form, which the certificates record.)
HsStatus hansen_sengupta(ModelEvaluator& ev, const Box& box, bool intersect,
                         std::vector<Interval>& image, HsWorkspace& ws, bool in_pose = false,
                         const std::vector<int>* unknowns = nullptr);

struct ExistenceProof {
  std::vector<Interval> inflated;  // [q̃k], double endpoints
  std::vector<Interval> image;     // [q(k+1)] = H([x],[q̃k]) rounded outward to doubles
  std::vector<double> C;           // preconditioner of the successful sweep
  int iterations = 0;
};

enum class Existence {
  Proved,      // the strict inclusion holds
  PoseSpread,  // not proved, and on the first sweep the pose alone spread some command's
               // image over at least half of its box: a narrower pose is what could help
  NotProved,   // not proved otherwise (two branches, a singular point, no contraction)
};

// Iteration (9) from the command part of `box`. On Existence::Proved, `proof` records the
// iterate, its image and the preconditioner. `in_pose`: in x, as for hansen_sengupta.
// With `grid`, each inflated end moves on out to the grid (proofs/certificate_grid.h) of
// that unknown's interval in *grid, the reference a format 3 certificate codes it against.
Existence prove_existence(ModelEvaluator& ev, const Box& box, double tau, int max_iterations,
                          ExistenceProof& proof, HsWorkspace& ws, bool in_pose = false,
                          const Box* grid = nullptr, const std::vector<int>* unknowns = nullptr);

// The Jacobian of f in the variables `vars` (model order indices), each column taken from Fx
// or Fq as its variable is a pose or a command: a chart's ∂_w f or ∂_u f.
template <class I>
void jacobian_columns(const Model& m, const Matrix<I>& Jx, const Matrix<I>& Jq,
                      const std::vector<int>& vars, Matrix<I>& out);

// Rounds both ends outward to doubles (a superset; identity at 53 bits).
void round_out_to_doubles(Interval& x);

}  // namespace aspects
