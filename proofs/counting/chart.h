// A chart of the solution set over a box (counting, certificates/FORMAT.md "Counting"):
// n of the 2n variables, w, as functions of the other n, u, over the whole of U:
//   V ∩ B ⊆ {(u, w(u)) : u ∈ U},  w continuous with values in RANGE.
// Proved as P1 is (iteration (9) of parametric Hansen–Sengupta, proofs/hansen_sengupta.h)
// with w the unknowns: the proof gives ∀u ∈ U ∃! w ∈ W̃, lying in RANGE ⊆ int W̃; with the
// box's W ⊆ W̃ every solution of B is on that graph (w is continuous: a closed graph in a
// compact set). The pose chart (w = the commands) fails near det Fq = 0, the command chart
// (w = the pose) near det Fx = 0; a mixed chart (some commands and some pose variables as
// w) holds where neither does, and is often the better fitted near one of them.
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

// The charts worth trying on a box, as their w, at most `limit`, best first: by the size of
// the box U × r their first-order graph fills (below), each width over `scale`, the
// variable's domain width (a choice in doubles; the proof decides). Near a serial
// singularity of one leg the likeliest chart is mixed, with that leg's command among u:
// ranking by conditioning alone put the nearly zero column of that command first.
std::vector<std::vector<int>> chart_candidates(ModelEvaluator& ev, const Box& box,
                                               const std::vector<double>& scale, int limit = 3);

// Where to cut a box on which no chart was proved (a choice in doubles, at the box's
// middle): for each candidate chart, the first-order range of w over U is
// r_j = Σ_k |X_jk|·|U_k| with X = (∂_w f)^{-1} ∂_u f; the proof works on U × (W ∪ r), so the
// chart whose such box is smallest (each width over `scale`, the variable's domain width) is
// the likeliest to be proved. Its widest w_j is cut when W_j is over twice r_j (a w-part the
// contraction left wide: its interval Jacobian loses the cancellations, and the halves
// contract around the graph), else the u_k that adds most to it. -1 when no candidate's
// ∂_w f is regular at the middle.
int chart_split_variable(ModelEvaluator& ev, const Box& box, const std::vector<double>& scale);

ChartVerdict prove_chart(ModelEvaluator& ev, const Box& box, const std::vector<int>& w,
                         HsWorkspace& ws, Chart& chart);

}  // namespace aspects
