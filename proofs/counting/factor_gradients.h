// The determinant factors g_1..g_p and their partial derivatives in every variable, as
// nodes of the model's DAG, and the enclosure of the gradient of φ_i(u) = g_i(u, w(u)) in a
// chart (proofs/counting/chart.h), by the implicit function theorem:
//   ∇φ_i = ∂_u g_i − ∂_w g_i · X,   X = (∂_w f)^{-1} ∂_u f.
// X is enclosed by a verified linear solve over the box, not a floating inverse: with
// C ≈ mid(∂_w f)^{-1} (a double choice), A = C·∂_w f, B = C·∂_u f and E = I − A, if
// β = ‖E‖_∞ < 1 then every point matrix of the box has X = B + E·X, ‖X_{·k}‖_∞ ≤ ρ_k =
// max_l |B_lk| / (1 − β), hence X_jk ∈ B_jk + Σ_l E_jl·[−ρ_k, ρ_k]. β < 1 also proves ∂_w f
// nonsingular on the box, so w is C¹ there.
#pragma once

#include <vector>

#include "counting/chart.h"
#include "model/model.h"
#include "model/model_eval.h"

namespace aspects {

class FactorGradients {
 public:
  // Adds the derivative nodes to model.dag: call before any evaluator of the model exists.
  FactorGradients(Model& model, const std::vector<int>& factor_nodes);

  int factors() const { return int(nodes_.size()); }
  int node(int i) const { return nodes_[i]; }
  // The factors' values on a box (all of them): false when one is undefined there.
  bool values(ModelEvaluator& ev, const Box& box, std::vector<Interval>& out) const;
  // Encloses X = (∂_w f)^{-1} ∂_u f over box z = (U, W) of chart `chart` (n×n, row j: the
  // derivatives of −w_j); false when it cannot (a node undefined, or β ≥ 1).
  bool implicit_jacobian(ModelEvaluator& ev, const Chart& chart, const Box& z, IMatrix& X) const;
  // Encloses ∇_u φ_i over z from X; false when a node is undefined.
  bool gradient(ModelEvaluator& ev, const Chart& chart, const Box& z, const IMatrix& X, int i,
                std::vector<Interval>& grad) const;

 private:
  std::vector<int> nodes_;
  std::vector<std::vector<int>> d_;  // d_[i][v]: d g_i / d var v
  std::vector<int> value_program_;
  std::vector<std::vector<int>> grad_program_;  // per factor: its derivatives' closure
};

}  // namespace aspects
