// A chart of the solution set over a box (counting, certificates/FORMAT.md "Counting"):
// n of the 2n variables, u, and a function w(u) over the whole of U such that
//   V ∩ B = {(u, w(u)) : u ∈ U, w(u) ∈ W}     (B = U × W).
// Proved as P1 is (iteration (9) of parametric Hansen–Sengupta, proofs/hansen_sengupta.h),
// with u the pose (w the commands) or u the commands (w the pose, Fx in Fq's role): the
// proof gives ∀u ∈ U ∃! w ∈ W̃, lying in IMAGE ⊆ int W̃; with W ⊆ W̃ every solution of B is
// on that graph. w is continuous (a closed graph in a compact set). Where the graph leaves B
// through a face of W, the piece is a graph over the part of U where w(u) ∈ W: the star
// test takes the faces w_j = lo_j, hi_j as constraints (counting/star_test.h). Near
// det Fq = 0 the pose chart fails; the command chart may then hold.
#pragma once

#include <cstdint>
#include <vector>

#include "hansen_sengupta.h"
#include "model/model_eval.h"

namespace aspects {

enum class ChartKind : uint8_t { Pose, Command };  // which variables are u

enum class ChartVerdict : uint8_t {
  Proved,      // the graph of w over U holds every solution of the box
  NoSolution,  // the box holds no solution (Hansen–Sengupta emptied W)
  NotProved,
};

struct Chart {
  ChartKind kind = ChartKind::Pose;
  std::vector<int> u, w;              // variable indices (model order), n each
  std::vector<Interval> w_range;      // IMAGE: w(U) lies in it (parallel to w)
};

// The variables of a chart of this kind: u then w.
void chart_variables(const Model& m, ChartKind kind, std::vector<int>& u, std::vector<int>& w);

ChartVerdict prove_chart(ModelEvaluator& ev, const Box& box, ChartKind kind, HsWorkspace& ws,
                         Chart& chart);

}  // namespace aspects
