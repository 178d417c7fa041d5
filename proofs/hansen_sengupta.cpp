#include "hansen_sengupta.h"

#include <algorithm>
#include <cmath>

#include "certificate_grid.h"
#include "numerics/interval_ops.h"
#include "preconditioner.h"

namespace aspects {

void round_out_to_doubles(Interval& x) { x.set_hull(x.lo_down(), x.hi_up()); }

template <class I>
void jacobian_columns(const Model& m, const Matrix<I>& Jx, const Matrix<I>& Jq,
                      const std::vector<int>& vars, Matrix<I>& out) {
  const int n = m.n();
  if (out.rows() != n || out.cols() != int(vars.size())) out = Matrix<I>(n, int(vars.size()));
  for (size_t j = 0; j < vars.size(); ++j) {
    const auto p = std::find(m.pose.begin(), m.pose.end(), vars[j]);
    const bool pose = p != m.pose.end();
    const int col = pose ? int(p - m.pose.begin())
                         : int(std::find(m.command.begin(), m.command.end(), vars[j]) -
                               m.command.begin());
    for (int i = 0; i < n; ++i) out(i, int(j)) = pose ? Jx(i, col) : Jq(i, col);
  }
}
template void jacobian_columns(const Model&, const Matrix<Interval>&, const Matrix<Interval>&,
                               const std::vector<int>&, Matrix<Interval>&);
template void jacobian_columns(const Model&, const Matrix<DInterval>&, const Matrix<DInterval>&,
                               const std::vector<int>&, Matrix<DInterval>&);

namespace {

// The Jacobian in the unknowns `u` (a chart's w).
template <class I>
EvalStatus mixed_jacobian(ModelEvaluator& ev, const Box& box, const std::vector<int>& u,
                          HsArrays<I>& w) {
  if (ev.jacobian_x(box, w.Jx) != EvalStatus::Defined) return EvalStatus::Undefined;
  if (ev.jacobian_q(box, w.Jq) != EvalStatus::Defined) return EvalStatus::Undefined;
  jacobian_columns(ev.model(), w.Jx, w.Jq, u, w.J);
  return EvalStatus::Defined;
}

// w.f0 = f(U, w̌) ∩ (f(ǔ, w̌) + ∂_u f(box)·(U − ǔ)), from the Jacobians mixed_jacobian left.
template <class I>
bool centred_meet(ModelEvaluator& ev, const Box& box, const std::vector<int>& unknowns,
                  HsWorkspace& ws, HsArrays<I>& w) {
  using namespace iops;
  const Model& m = ev.model();
  const int n = m.n();
  std::vector<int> params;
  for (int v = 0; v < int(m.vars.size()); ++v)
    if (std::find(unknowns.begin(), unknowns.end(), v) == unknowns.end()) params.push_back(v);
  Box centre = ws.mid_box;
  std::vector<double> umid(params.size());
  for (size_t k = 0; k < params.size(); ++k) {
    umid[k] = box[params[k]].mid();
    if (!std::isfinite(umid[k])) return false;
    centre[params[k]].set_point(umid[k]);
  }
  if (ev.equations(centre, w.fc) != EvalStatus::Defined) return false;
  jacobian_columns(m, w.Jx, w.Jq, params, w.Jp);
  I t;
  for (int i = 0; i < n; ++i) {
    for (size_t k = 0; k < params.size(); ++k) {
      assign(t, box[params[k]]);
      sub_d(t, umid[k]);
      mul_into(t, w.Jp(i, int(k)));
      add_to(w.fc[i], t);
    }
    // Both enclose f_i(U, w̌): they meet. An empty meet is rounding noise, never a proof.
    if (!meet_of(t, w.f0[i], w.fc[i])) return false;
    w.f0[i] = t;
  }
  return true;
}

template <class I>
HsStatus sweep(ModelEvaluator& ev, const Box& box, bool intersect, std::vector<Interval>& image,
               HsWorkspace& ws, HsArrays<I>& w, bool in_pose, const std::vector<int>* unknowns) {
  using namespace iops;
  const Model& m = ev.model();
  const int n = m.n();
  const std::vector<int>& u = unknowns ? *unknowns : in_pose ? m.pose : m.command;  // the unknowns
  // Mean-value form around a point of [q]: f(x,q) = f(x,q̌) + Fq(x,ξ)(q − q̌).
  ws.mid_box = box;
  std::vector<double> qmid(n);
  w.q.resize(n);
  for (int j = 0; j < n; ++j) {
    qmid[j] = box[u[j]].mid();
    if (!std::isfinite(qmid[j])) return HsStatus::Failed;
    ws.mid_box[u[j]].set_point(qmid[j]);
    assign(w.q[j], box[u[j]]);
  }
  if (ev.equations(ws.mid_box, w.f0) != EvalStatus::Defined) return HsStatus::Failed;
  const EvalStatus J = unknowns  ? mixed_jacobian(ev, box, u, w)
                       : in_pose ? ev.jacobian_x(box, w.J)
                                 : ev.jacobian_q(box, w.J);
  if (J != EvalStatus::Defined) return HsStatus::Failed;
  if (unknowns && !centred_meet(ev, box, *unknowns, ws, w)) return HsStatus::Failed;
  if (!approximate_inverse(w.J, ws.C)) return HsStatus::Failed;
  if (w.A.rows() != n) w.A = Matrix<I>(n, n);
  w.b.resize(n);
  for (int i = 0; i < n; ++i) {
    preconditioned_entry(ws.C, w.f0, i, w.b[i], w.t1);
    for (int j = 0; j < n; ++j) preconditioned_entry(ws.C, w.J, i, j, w.A(i, j), w.t1);
  }
  // Gauss–Seidel: component j < i uses its new value (intersected with the box).
  std::vector<I>& y = w.y;
  y.resize(n);
  for (int i = 0; i < n; ++i) {
    if (contains_zero(w.A(i, i))) return HsStatus::Failed;
    w.t2 = w.b[i];
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      if (j < i) {
        if (!meet_of(w.t1, y[j], w.q[j])) return HsStatus::NoSolution;
      } else {
        w.t1 = w.q[j];
      }
      sub_d(w.t1, qmid[j]);
      mul_into(w.t1, w.A(i, j));
      add_to(w.t2, w.t1);
    }
    div_into(w.t2, w.A(i, i));
    d_sub(y[i], qmid[i], w.t2);
    if (!usable(y[i])) return HsStatus::Failed;
    if (intersect) {
      if (!meet_of(y[i], y[i], w.q[i])) return HsStatus::NoSolution;
    } else {
      if (!meet_of(w.t1, y[i], w.q[i])) return HsStatus::NoSolution;
    }
  }
  image.resize(n);
  for (int i = 0; i < n; ++i) store(image[i], y[i]);
  return HsStatus::Ok;
}

}  // namespace

HsStatus hansen_sengupta(ModelEvaluator& ev, const Box& box, bool intersect,
                         std::vector<Interval>& image, HsWorkspace& ws, bool in_pose,
                         const std::vector<int>* unknowns) {
  ws.in_doubles = ev.arithmetic() == Arithmetic::DoublesFirst;
  if (ws.in_doubles) return sweep(ev, box, intersect, image, ws, ws.doubles, in_pose, unknowns);
  return sweep(ev, box, intersect, image, ws, ws.mpfi, in_pose, unknowns);
}

namespace {

// Row i of the sweep divides C·f([x], mid q) by (C·Fq)_ii: the quotient is at least
// w(b_i) / mag(A_ii) wide whatever the commands, so when that is half the box or more,
// the pose's spread blocks the inclusion (a heuristic for the bisector, not a proof).
template <class I>
bool pose_spreads(const HsArrays<I>& w, const std::vector<Interval>& q) {
  for (size_t i = 0; i < q.size(); ++i) {
    double mag = std::max(std::fabs(iops::lo(w.A(i, i))), std::fabs(iops::hi(w.A(i, i))));
    if (iops::width(w.b[i]) >= 0.5 * mag * q[i].width_up()) return true;
  }
  return false;
}

bool pose_spreads(const HsWorkspace& ws, const std::vector<Interval>& q) {
  return ws.in_doubles ? pose_spreads(ws.doubles, q) : pose_spreads(ws.mpfi, q);
}

}  // namespace

Existence prove_existence(ModelEvaluator& ev, const Box& box, double tau, int max_iterations,
                          ExistenceProof& proof, HsWorkspace& ws, bool in_pose,
                          const Box* grid, const std::vector<int>* unknowns) {
  const Model& m = ev.model();
  const int n = m.n();
  const std::vector<int>& u = unknowns ? *unknowns : in_pose ? m.pose : m.command;
  Box work = box;
  proof.inflated.resize(n);
  std::vector<Interval> y;
  Existence failure = Existence::NotProved;
  double start_width = 0;
  for (int j = 0; j < n; ++j) start_width = std::max(start_width, box[u[j]].width_up());
  for (int k = 0; k < max_iterations; ++k) {
    // [q̃k] = mid + τ([qk] − mid): a choice, made in double and rounded outward.
    for (int j = 0; j < n; ++j) {
      Interval& q = work[u[j]];
      double lo = q.lo_down(), hi = q.hi_up(), mid = q.mid();
      double nlo = mid - tau * (mid - lo), nhi = mid + tau * (hi - mid);
      nlo = std::nextafter(std::min(nlo, lo), -INFINITY);
      nhi = std::nextafter(std::max(nhi, hi), INFINITY);
      if (grid) {
        const double a = (*grid)[u[j]].lo_down(), b = (*grid)[u[j]].hi_up();
        const double step = grid::step(a, b);
        nlo = grid::snap(nlo, a, step, false);
        nhi = grid::snap(nhi, b, step, true);
      }
      q.set_hull(nlo, nhi);
      proof.inflated[j] = q;
    }
    HsStatus s = hansen_sengupta(ev, work, false, y, ws, in_pose, unknowns);
    if (s != HsStatus::Ok) return failure;
    if (k == 0 && pose_spreads(ws, proof.inflated)) failure = Existence::PoseSpread;
    bool inside = true;
    double width = 0;
    for (int j = 0; j < n; ++j) {
      round_out_to_doubles(y[j]);
      if (!proof.inflated[j].strictly_contains(y[j])) inside = false;
      width = std::max(width, y[j].width_up());
    }
    if (inside) {
      proof.image = y;
      proof.C = ws.C;
      proof.iterations = k + 1;
      return Existence::Proved;
    }
    if (!(width <= 4 * start_width + 1e-300)) return failure;  // diverging
    for (int j = 0; j < n; ++j) work[u[j]] = y[j];
  }
  return failure;
}

}  // namespace aspects
