#include "results/point_command.h"

#include <algorithm>
#include <cmath>

#include "strong_regularity.h"

namespace aspects {

namespace {

// Newton on f(x, ·) = 0 in double (point evaluations, their midpoints). Returns false when
// it does not converge or leaves [q] (widened by its width): the box proof takes over.
bool newton_in_double(ModelEvaluator& ev, Box& point, const double* lo, const double* hi,
                      std::vector<double>& q, int& iterations) {
  const Model& m = ev.model();
  const int n = m.n();
  std::vector<Interval> f;
  IMatrix J;
  std::vector<double> C;
  double step = INFINITY, size = 0;
  for (iterations = 1; iterations <= 30; ++iterations) {
    for (int j = 0; j < n; ++j) point[m.command[j]].set_point(q[j]);
    if (ev.equations(point, f) != EvalStatus::Defined) return false;
    if (ev.jacobian_q(point, J) != EvalStatus::Defined) return false;
    if (!approximate_inverse(J, C)) return false;
    step = 0;
    size = 0;
    for (int i = 0; i < n; ++i) {
      double d = 0;
      for (int k = 0; k < n; ++k) d += C[size_t(i) * n + k] * f[k].mid();
      q[i] -= d;
      step = std::max(step, std::fabs(d));
      size = std::max(size, std::fabs(q[i]));
    }
    for (int j = 0; j < n; ++j) {
      int v = m.command[j];
      double w = hi[v] - lo[v];
      if (!(q[j] >= lo[v] - w && q[j] <= hi[v] + w)) return false;
    }
    if (step <= 1e-14 * (1 + size)) return true;
  }
  // Rounding can keep the last steps above 1e-14 near an ill-conditioned root; the proof
  // around q (radius 1e-9) still succeeds when q is that close.
  iterations = 30;
  return step <= 1e-11 * (1 + size);
}

// Iteration (9) at the point pose from the command box `start`; Certified when the
// proved enclosure lies in the solution box's [q].
bool prove_inside(ModelEvaluator& ev, Box& w, const double* lo, const double* hi, double tau,
                  HsWorkspace& ws, PointCommand& out) {
  const Model& m = ev.model();
  ExistenceProof proof;
  if (prove_existence(ev, w, tau, 8, proof, ws) != Existence::Proved) return false;
  out.lo.assign(m.n(), 0.0);
  out.hi.assign(m.n(), 0.0);
  for (int j = 0; j < m.n(); ++j) {
    int v = m.command[j];
    out.lo[j] = proof.image[j].lo_down();
    out.hi[j] = proof.image[j].hi_up();
    if (!(lo[v] <= out.lo[j] && out.hi[j] <= hi[v])) return false;
  }
  out.status = PointCommandStatus::Certified;
  return true;
}

}  // namespace

double PointCommand::width() const {
  double w = 0;
  for (size_t j = 0; j < lo.size(); ++j) w = std::max(w, hi[j] - lo[j]);
  return w;
}

PointCommand certified_command(ModelEvaluator& ev, const double* lo, const double* hi,
                               const std::vector<double>& pose, double tau, HsWorkspace& ws) {
  const Model& m = ev.model();
  const int n = m.n();
  Box w(m.vars.size());
  for (int j = 0; j < n; ++j) w[m.pose[j]].set_point(pose[j]);
  std::vector<double> q(n);
  for (int j = 0; j < n; ++j) q[j] = 0.5 * lo[m.command[j]] + 0.5 * hi[m.command[j]];
  PointCommand out;
  if (newton_in_double(ev, w, lo, hi, q, out.newton_iterations)) {
    // A small box around the Newton root: the proof's enclosure is then a few ulps wide.
    for (int j = 0; j < n; ++j) {
      double r = 1e-9 * (1 + std::fabs(q[j]));
      w[m.command[j]].set_hull(q[j] - r, q[j] + r);
    }
    out.start = PointCommandStart::Newton;
    if (prove_inside(ev, w, lo, hi, tau, ws, out)) return out;
  }
  for (int j = 0; j < n; ++j) w[m.command[j]].set_hull(lo[m.command[j]], hi[m.command[j]]);
  out.start = PointCommandStart::WholeBox;
  out.status = PointCommandStatus::NotProved;
  if (prove_inside(ev, w, lo, hi, tau, ws, out)) return out;
  out.lo.clear();
  out.hi.clear();
  return out;
}

}  // namespace aspects
