#include "counting/factor_gradients.h"

#include <algorithm>
#include <cmath>

#include "hansen_sengupta.h"
#include "numerics/interval_ops.h"
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

template <class I>
double mag(const I& x) {
  return std::max(std::fabs(iops::lo(x)), std::fabs(iops::hi(x)));
}
void set_d(Interval& r, double lo, double hi) { r.set_hull(lo, hi); }
void set_d(DInterval& r, double lo, double hi) { r = {lo, hi}; }

// The verified solve of implicit_jacobian on Jacobians of either kind of interval (double
// ends at 53 bits, as the search's sweeps; MPFI otherwise); X is stored in MPFI.
template <class I>
bool implicit_solve(const Model& m, const Chart& chart, const Matrix<I>& Jx, const Matrix<I>& Jq,
                    IMatrix& X) {
  using namespace iops;
  const int n = m.n();
  // ∂_u f and ∂_w f.
  Matrix<I> Ju, Jw;
  jacobian_columns(m, Jx, Jq, chart.u, Ju);
  jacobian_columns(m, Jx, Jq, chart.w, Jw);
  std::vector<double> C;
  if (!approximate_inverse(Jw, C)) return false;
  Matrix<I> E(n, n), B(n, n);
  I t, scratch;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      preconditioned_entry(C, Jw, r, c, t, scratch);
      d_sub(E(r, c), r == c ? 1.0 : 0.0, t);  // E = I − C·∂_w f
      preconditioned_entry(C, Ju, r, c, B(r, c), scratch);
    }
  // β = ‖E‖_∞, rounded up (each row's sum of magnitudes, outward).
  double beta = 0;
  I row;
  for (int r = 0; r < n; ++r) {
    set_zero(row);
    for (int c = 0; c < n; ++c) {
      set_d(t, mag(E(r, c)), mag(E(r, c)));
      add_to(row, t);
    }
    beta = std::max(beta, hi(row));
  }
  if (!(beta < 1.0)) return false;
  I one_minus;
  set_d(t, beta, beta);
  d_sub(one_minus, 1.0, t);  // 1 − β, outward
  // X_jk ∈ B_jk + Σ_l E_jl·[−ρ_k, ρ_k].
  X = IMatrix(n, n);
  I rho, x;
  for (int k = 0; k < n; ++k) {
    double maxb = 0;
    for (int l = 0; l < n; ++l) maxb = std::max(maxb, mag(B(l, k)));
    set_d(rho, maxb, maxb);
    div_into(rho, one_minus);
    const double r = hi(rho);
    if (!std::isfinite(r)) return false;
    set_d(rho, -r, r);
    for (int j = 0; j < n; ++j) {
      x = B(j, k);
      for (int l = 0; l < n; ++l) {
        t = E(j, l);
        mul_into(t, rho);
        add_to(x, t);
      }
      if (!usable(x)) return false;
      store(X(j, k), x);
    }
  }
  return true;
}

}  // namespace

bool FactorGradients::implicit_jacobian(ModelEvaluator& ev, const Chart& chart, const Box& z,
                                        IMatrix& X) const {
  if (ev.arithmetic() == Arithmetic::DoublesFirst) {
    DMatrix Jx, Jq;
    if (ev.jacobian_x(z, Jx) != EvalStatus::Defined || ev.jacobian_q(z, Jq) != EvalStatus::Defined)
      return false;
    return implicit_solve(ev.model(), chart, Jx, Jq, X);
  }
  IMatrix Jx, Jq;
  if (ev.jacobian_x(z, Jx) != EvalStatus::Defined || ev.jacobian_q(z, Jq) != EvalStatus::Defined)
    return false;
  return implicit_solve(ev.model(), chart, Jx, Jq, X);
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
