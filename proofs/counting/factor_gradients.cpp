#include "counting/factor_gradients.h"

#include <algorithm>
#include <cmath>

#include "hansen_sengupta.h"
#include "preconditioner.h"

namespace aspects {

FactorGradients::FactorGradients(Model& model, const std::vector<int>& factor_nodes)
    : nodes_(factor_nodes) {
  const int nv = int(model.vars.size());
  for (int g : nodes_) {
    std::vector<int> row(nv);
    for (int v = 0; v < nv; ++v) row[v] = model.dag.derivative(g, v);
    d_.push_back(row);
  }
  value_program_ = model.dag.closure(nodes_);
  for (const auto& row : d_) grad_program_.push_back(model.dag.closure(row));
}

bool FactorGradients::values(ModelEvaluator& ev, const Box& box, std::vector<Interval>& out) const {
  if (ev.nodes(value_program_, box) != EvalStatus::Defined) return false;
  out.resize(nodes_.size());
  for (size_t i = 0; i < nodes_.size(); ++i) out[i] = ev.value(nodes_[i]);
  return true;
}

namespace {

double mag(const Interval& x) { return std::max(std::fabs(x.lo_down()), std::fabs(x.hi_up())); }

}  // namespace

bool FactorGradients::implicit_jacobian(ModelEvaluator& ev, const Chart& chart, const Box& z,
                                        IMatrix& X) const {
  const int n = ev.n();
  const Model& m = ev.model();
  IMatrix Jx, Jq;
  if (ev.jacobian_x(z, Jx) != EvalStatus::Defined || ev.jacobian_q(z, Jq) != EvalStatus::Defined)
    return false;
  // ∂_u f and ∂_w f.
  IMatrix Ju, Jw;
  jacobian_columns(m, Jx, Jq, chart.u, Ju);
  jacobian_columns(m, Jx, Jq, chart.w, Jw);
  std::vector<double> C;
  if (!approximate_inverse(Jw, C)) return false;
  IMatrix E(n, n), B(n, n);
  Interval t;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      preconditioned_entry(C, Jw, r, c, E(r, c), t);
      mpfi_d_sub(E(r, c).get(), r == c ? 1.0 : 0.0, E(r, c).get());  // E = I − C·∂_w f
      preconditioned_entry(C, Ju, r, c, B(r, c), t);
    }
  // β = ‖E‖_∞, rounded up (each row's sum of magnitudes in MPFI).
  Interval beta(0.0), row;
  for (int r = 0; r < n; ++r) {
    row.set_point(0.0);
    for (int c = 0; c < n; ++c) mpfi_add_d(row.get(), row.get(), mag(E(r, c)));
    if (row.hi_up() > beta.hi_up()) beta.set_point(row.hi_up());
  }
  if (!(beta.hi_up() < 1.0)) return false;
  Interval one_minus(1.0);
  mpfi_sub(one_minus.get(), one_minus.get(), beta.get());
  // X_jk ∈ B_jk + Σ_l E_jl·[−ρ_k, ρ_k].
  X = IMatrix(n, n);
  for (int k = 0; k < n; ++k) {
    double maxb = 0;
    for (int l = 0; l < n; ++l) maxb = std::max(maxb, mag(B(l, k)));
    Interval rho(maxb);
    mpfi_div(rho.get(), rho.get(), one_minus.get());
    const double r = rho.hi_up();
    if (!std::isfinite(r)) return false;
    Interval box_rho(-r, r);
    for (int j = 0; j < n; ++j) {
      X(j, k) = B(j, k);
      for (int l = 0; l < n; ++l) {
        mpfi_mul(t.get(), E(j, l).get(), box_rho.get());
        mpfi_add(X(j, k).get(), X(j, k).get(), t.get());
      }
    }
  }
  return true;
}

bool FactorGradients::gradient(ModelEvaluator& ev, const Chart& chart, const Box& z,
                               const IMatrix& X, int i, std::vector<Interval>& grad) const {
  const int n = ev.n();
  Interval t;
  if (ev.nodes(grad_program_[i], z) != EvalStatus::Defined) return false;
  std::vector<Interval> dw(n);
  for (int j = 0; j < n; ++j) dw[j] = ev.value(d_[i][chart.w[j]]);
  grad.resize(n);
  for (int k = 0; k < n; ++k) {
    grad[k] = ev.value(d_[i][chart.u[k]]);
    for (int j = 0; j < n; ++j) {
      mpfi_mul(t.get(), dw[j].get(), X(j, k).get());
      mpfi_sub(grad[k].get(), grad[k].get(), t.get());
    }
    if (!grad[k].bounded() || grad[k].empty()) return false;
  }
  return true;
}

}  // namespace aspects
