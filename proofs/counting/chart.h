// A chart of the solution set over a box (counting, certificates/FORMAT.md "Counting"):
// n of the 2n variables, w, as functions of the other n, u, over the whole of U:
//   V ∩ B ⊆ {(u, w(u)) : u ∈ U},  w continuous with values in RANGE.
// Proved as P1 is (iteration (9) of parametric Hansen–Sengupta, proofs/hansen_sengupta.h)
// with w the unknowns: the proof gives ∀u ∈ U ∃! w ∈ W̃, lying in RANGE ⊆ int W̃; with the
// box's W ⊆ W̃ every solution of B is on that graph (w is continuous: a closed graph in a
// compact set). The pose chart (w = the commands) fails near det Fq = 0, the command chart
// (w = the pose) near det Fx = 0; where both vanish, a mixed chart (the columns of [Fx Fq]
// best conditioned at the box's middle) may hold.
#pragma once

#include <cstdint>
#include <vector>

#include "hansen_sengupta.h"
#include "model/model_eval.h"

namespace aspects {

enum class ChartVerdict : uint8_t {
  Proved,      // the graph of w over U holds every solution of the box
  NoSolution,  // the box holds no solution (Hansen–Sengupta emptied W)
  NotProved,
};

struct Chart {
  std::vector<int> u, w;              // variable indices (model order), n each
  std::vector<Interval> w_range;      // RANGE: w(U) lies in it (parallel to w)
  std::vector<Interval> w_tilde;      // W̃: the iterate holding the box's W and RANGE in its
                                      // interior (the unique w(u) of U is in it; certificate)
};

// u: the variables not in w, in model order.
std::vector<int> chart_complement(const Model& m, const std::vector<int>& w);

// The charts worth trying on a box, as their w, best first: the pose chart, the command
// chart, then at most `mixed` others by the conditioning of their Jacobian at the box's
// middle (a choice in doubles; the proof decides).
std::vector<std::vector<int>> chart_candidates(ModelEvaluator& ev, const Box& box, int mixed = 2);

// Where to cut a box on which no chart was proved (a choice in doubles, at the box's
// middle): for each candidate chart, the first-order range of w over U is
// r_j = Σ_k |X_jk|·|U_k| with X = (∂_w f)^{-1} ∂_u f; the chart whose box U × r is smallest
// (each width over `scale`, the variable's domain width) is the likeliest to be proved, and
// the u_k that adds most to it is cut. Cutting a w instead would leave U, and the graph's
// range over it, as wide as before. -1 when no candidate's ∂_w f is regular at the middle.
int chart_split_variable(ModelEvaluator& ev, const Box& box, const std::vector<double>& scale);

ChartVerdict prove_chart(ModelEvaluator& ev, const Box& box, const std::vector<int>& w,
                         HsWorkspace& ws, Chart& chart);

}  // namespace aspects
