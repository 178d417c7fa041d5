#include "hansen_sengupta.h"

#include <cmath>

#include "preconditioner.h"

namespace aspects {

void round_out_to_doubles(Interval& x) { x.set_hull(x.lo_down(), x.hi_up()); }

HsStatus hansen_sengupta(ModelEvaluator& ev, const Box& box, bool intersect,
                         std::vector<Interval>& image, HsWorkspace& ws, bool in_pose) {
  const Model& m = ev.model();
  const int n = m.n();
  const std::vector<int>& u = in_pose ? m.pose : m.command;  // the unknowns
  // Mean-value form around a point of [q]: f(x,q) = f(x,q̌) + Fq(x,ξ)(q − q̌).
  ws.mid_box = box;
  std::vector<double> qmid(n);
  for (int j = 0; j < n; ++j) {
    qmid[j] = box[u[j]].mid();
    if (!std::isfinite(qmid[j])) return HsStatus::Failed;
    ws.mid_box[u[j]].set_point(qmid[j]);
  }
  if (ev.equations(ws.mid_box, ws.f0) != EvalStatus::Defined) return HsStatus::Failed;
  const EvalStatus J = in_pose ? ev.jacobian_x(box, ws.J) : ev.jacobian_q(box, ws.J);
  if (J != EvalStatus::Defined) return HsStatus::Failed;
  if (!approximate_inverse(ws.J, ws.C)) return HsStatus::Failed;
  if (ws.A.rows() != n) ws.A = IMatrix(n, n);
  ws.b.resize(n);
  for (int i = 0; i < n; ++i) {
    preconditioned_entry(ws.C, ws.f0, i, ws.b[i], ws.t1);
    for (int j = 0; j < n; ++j) preconditioned_entry(ws.C, ws.J, i, j, ws.A(i, j), ws.t1);
  }
  image.resize(n);
  // Gauss–Seidel: component j < i uses its new value (intersected with the box).
  std::vector<Interval>& y = image;
  for (int i = 0; i < n; ++i) {
    if (ws.A(i, i).contains_zero()) return HsStatus::Failed;
    mpfi_set(ws.t2.get(), ws.b[i].get());
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      const Interval& qj = box[u[j]];
      if (j < i) {
        mpfi_intersect(ws.t1.get(), y[j].get(), qj.get());
        if (ws.t1.empty()) return HsStatus::NoSolution;
      } else {
        mpfi_set(ws.t1.get(), qj.get());
      }
      mpfi_sub_d(ws.t1.get(), ws.t1.get(), qmid[j]);
      mpfi_mul(ws.t1.get(), ws.t1.get(), ws.A(i, j).get());
      mpfi_add(ws.t2.get(), ws.t2.get(), ws.t1.get());
    }
    mpfi_div(ws.t2.get(), ws.t2.get(), ws.A(i, i).get());
    mpfi_d_sub(y[i].get(), qmid[i], ws.t2.get());
    if (!y[i].bounded() || y[i].empty()) return HsStatus::Failed;
    if (intersect) {
      if (!y[i].intersect(box[u[i]])) return HsStatus::NoSolution;
    } else {
      mpfi_intersect(ws.t1.get(), y[i].get(), box[u[i]].get());
      if (ws.t1.empty()) return HsStatus::NoSolution;
    }
  }
  return HsStatus::Ok;
}

namespace {

// Row i of the sweep divides C·f([x], mid q) by (C·Fq)_ii: the quotient is at least
// w(b_i) / mag(A_ii) wide whatever the commands, so when that is half the box or more,
// the pose's spread blocks the inclusion (a heuristic for the bisector, not a proof).
bool pose_spreads(const HsWorkspace& ws, const std::vector<Interval>& q) {
  for (size_t i = 0; i < q.size(); ++i) {
    double mag = std::max(std::fabs(ws.A(i, i).lo_down()), std::fabs(ws.A(i, i).hi_up()));
    if (ws.b[i].width_up() >= 0.5 * mag * q[i].width_up()) return true;
  }
  return false;
}

}  // namespace

Existence prove_existence(ModelEvaluator& ev, const Box& box, double tau, int max_iterations,
                          ExistenceProof& proof, HsWorkspace& ws, bool in_pose) {
  const Model& m = ev.model();
  const int n = m.n();
  const std::vector<int>& u = in_pose ? m.pose : m.command;
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
      q.set_hull(nlo, nhi);
      proof.inflated[j] = q;
    }
    HsStatus s = hansen_sengupta(ev, work, false, y, ws, in_pose);
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
