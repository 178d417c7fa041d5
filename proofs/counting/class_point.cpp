#include "counting/class_point.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace aspects {

namespace {

struct Candidate {
  double margin;
  std::vector<double> u, w;
};

// Newton in doubles for w at the u-point, from the middle of the box's w-part: a choice.
bool newton_w(ModelEvaluator& ev, const Box& box, const std::vector<int>& w,
              std::vector<double>& wpt) {
  const int n = ev.n();
  Box pt = box;
  for (int j = 0; j < n; ++j) pt[w[j]].set_point(box[w[j]].mid());
  const Model& m = ev.model();
  std::vector<Interval> f;
  IMatrix Jx, Jq, Jw;
  Eigen::MatrixXd A(n, n);
  Eigen::VectorXd b(n);
  for (int it = 0; it < 30; ++it) {
    if (ev.equations(pt, f) != EvalStatus::Defined) return false;
    if (ev.jacobian_x(pt, Jx) != EvalStatus::Defined || ev.jacobian_q(pt, Jq) != EvalStatus::Defined)
      return false;
    for (int i = 0; i < n; ++i) b(i) = f[i].mid();
    jacobian_columns(m, Jx, Jq, w, Jw);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) A(i, j) = Jw(i, j).mid();
    Eigen::VectorXd dx = A.fullPivLu().solve(b);
    if (!dx.allFinite()) return false;
    double step = 0;
    for (int j = 0; j < n; ++j) {
      const double x = pt[w[j]].mid() - dx(j);
      pt[w[j]].set_point(x);
      step = std::max(step, std::fabs(dx(j)) / (1 + std::fabs(x)));
    }
    if (step < 1e-15) break;
  }
  wpt.resize(n);
  for (int j = 0; j < n; ++j) {
    wpt[j] = pt[w[j]].mid();
    if (!(wpt[j] >= box[w[j]].lo_down() && wpt[j] <= box[w[j]].hi_up())) return false;
  }
  return true;
}

}  // namespace

PointVerdict find_class_point(ModelEvaluator& ev, const FactorGradients& fg, const Box& box,
                              const std::vector<int>& w, uint32_t cls, HsWorkspace& ws,
                              ClassPoint& out, int per_axis) {
  const Model& m = ev.model();
  const int n = ev.n(), p = fg.factors();
  const std::vector<int> u = chart_complement(m, w);
  // The grid of u-points: per axis the centres of per_axis equal cells (one point on a
  // degenerate axis).
  std::vector<Candidate> found;
  std::vector<int> idx(n, 0);
  std::vector<Interval> values, whole;
  // Scales of the factors over the box, to compare their margins with the faces'.
  const bool scaled = fg.values(ev, box, whole);
  Box pt = box;
  // The depth of a u-point in the piece: the least of the factors' margins (relative to
  // their range over the box) and the distances to the faces of W (relative to its width);
  // a star centre deep inside has the best chance. False when Newton leaves the box.
  auto depth = [&](Candidate& c) {
    for (int k = 0; k < n; ++k) pt[u[k]].set_point(c.u[k]);
    const bool ok = newton_w(ev, pt, w, c.w);
    if (ok) {
      for (int j = 0; j < n; ++j) pt[w[j]].set_point(c.w[j]);
      c.margin = -INFINITY;
      if (fg.values(ev, pt, values)) {
        c.margin = INFINITY;
        for (int i = 0; i < p; ++i) {
          const double s = (cls >> i) & 1 ? 1.0 : -1.0;
          const double g = s * values[i].mid();
          double scale = std::fabs(values[i].mid());
          if (scaled) scale = std::max(std::fabs(whole[i].lo_down()), std::fabs(whole[i].hi_up()));
          c.margin = std::min(c.margin, g / (scale > 0 ? scale : 1.0));
        }
        for (int j = 0; j < n; ++j) {
          const double lo = box[w[j]].lo_down(), hi = box[w[j]].hi_up();
          if (hi > lo) c.margin = std::min(c.margin, std::min(c.w[j] - lo, hi - c.w[j]) / (hi - lo));
        }
      }
      for (int j = 0; j < n; ++j) pt[w[j]] = box[w[j]];
    }
    return ok;
  };
  Candidate best;
  best.margin = -INFINITY;
  for (;;) {
    Candidate c;
    c.u.resize(n);
    for (int k = 0; k < n; ++k) {
      const double lo = box[u[k]].lo_down(), hi = box[u[k]].hi_up();
      const int cells = lo == hi ? 1 : per_axis;
      c.u[k] = std::min(hi, std::max(lo, lo + (hi - lo) * (idx[k] + 0.5) / cells));
    }
    if (depth(c)) {
      if (c.margin > 0) found.push_back(c);
      if (c.margin > best.margin) best = c;
    }
    int k = 0;
    for (; k < n; ++k) {
      const int cells = box[u[k]].lo_down() == box[u[k]].hi_up() ? 1 : per_axis;
      if (++idx[k] < cells) break;
      idx[k] = 0;
    }
    if (k == n) break;
  }
  // A piece that is a sliver (the class cut off by a singular surface near a corner of the
  // box) holds no grid point: climb from the deepest one, coordinate by coordinate, with
  // halving steps, towards more depth.
  if (found.empty() && !best.u.empty()) {
    std::vector<double> step(n);
    for (int k = 0; k < n; ++k) step[k] = 0.25 * box[u[k]].width_up() / per_axis;
    for (int it = 0; it < 48; ++it) {
      bool moved = false;
      for (int k = 0; k < n; ++k)
        for (double dir : {-1.0, 1.0}) {
          Candidate c = best;
          c.u[k] = std::min(box[u[k]].hi_up(), std::max(box[u[k]].lo_down(), c.u[k] + dir * step[k]));
          if (c.u[k] != best.u[k] && depth(c) && c.margin > best.margin) best = c, moved = true;
        }
      if (!moved)
        for (double& h : step) h *= 0.5;
      if (best.margin > 0 && !moved) break;
    }
    if (best.margin > 0) found.push_back(best);
  }
  std::sort(found.begin(), found.end(),
            [](const Candidate& a, const Candidate& b) { return a.margin > b.margin; });
  if (found.size() > 4) found.resize(4);
  ExistenceProof proof;
  for (const Candidate& c : found) {
    Box z = box;
    for (int k = 0; k < n; ++k) z[u[k]].set_point(c.u[k]);
    for (int j = 0; j < n; ++j) {
      const double r = 1e-12 * (1 + std::fabs(c.w[j]));
      z[w[j]].set_hull(c.w[j] - r, c.w[j] + r);
    }
    if (prove_existence(ev, z, 1.01, 12, proof, ws, false, nullptr, &w) != Existence::Proved)
      continue;
    bool inside = true;
    for (int j = 0; j < n; ++j) {
      if (!box[w[j]].contains(proof.image[j])) inside = false;
      z[w[j]] = proof.image[j];
    }
    if (!inside || !fg.values(ev, z, values)) continue;
    bool signs = true;
    for (int i = 0; i < p; ++i) {
      const bool positive = (cls >> i) & 1;
      if (!(positive ? values[i].certainly_pos() : values[i].certainly_neg())) signs = false;
    }
    if (!signs) continue;
    out.u_vars = u;
    out.w_vars = w;
    out.u = c.u;
    out.w = proof.image;
    return PointVerdict::Found;
  }
  return PointVerdict::NotFound;
}

}  // namespace aspects
