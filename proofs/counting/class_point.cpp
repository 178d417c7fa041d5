#include "counting/class_point.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace aspects {

namespace {

// Newton in doubles for w at the u-point of `pt` (its w-part: the box's), from `start` or
// the middle of the w-part: a choice. False when it fails. It may end outside the w-part:
// in a box cut across a thin strip of the graph most u-points have their w outside, and
// how far outside tells the climb where the strip lies.
bool newton_w(ModelEvaluator& ev, Box& pt, const Box& box, const std::vector<int>& w,
              const std::vector<double>* start, std::vector<double>& wpt) {
  const int n = ev.n(), nv = int(pt.size());
  const Model& m = ev.model();
  // Each w's column in Fx or Fq, row major there.
  std::vector<std::pair<bool, int>> col(n);
  for (int j = 0; j < n; ++j) {
    const auto p = std::find(m.pose.begin(), m.pose.end(), w[j]);
    col[j] = p != m.pose.end()
                 ? std::make_pair(true, int(p - m.pose.begin()))
                 : std::make_pair(false, int(std::find(m.command.begin(), m.command.end(), w[j]) -
                                             m.command.begin()));
  }
  std::vector<double> v(nv), f, fx, fq;
  for (int i = 0; i < nv; ++i) v[i] = pt[i].mid();
  for (int j = 0; j < n; ++j) v[w[j]] = start ? (*start)[j] : box[w[j]].mid();
  Eigen::MatrixXd A(n, n);
  Eigen::VectorXd b(n);
  for (int it = 0; it < 30; ++it) {
    if (!ev.at_point(v.data(), f, fx, fq)) return false;
    for (int i = 0; i < n; ++i) {
      b(i) = f[i];
      for (int j = 0; j < n; ++j) A(i, j) = (col[j].first ? fx : fq)[i * n + col[j].second];
    }
    const Eigen::VectorXd dx = A.fullPivLu().solve(b);
    if (!dx.allFinite()) return false;
    double step = 0;
    for (int j = 0; j < n; ++j) {
      v[w[j]] -= dx(j);
      step = std::max(step, std::fabs(dx(j)) / (1 + std::fabs(v[w[j]])));
    }
    if (step < 1e-15) break;
  }
  wpt.resize(n);
  for (int j = 0; j < n; ++j) {
    wpt[j] = v[w[j]];
    if (!std::isfinite(wpt[j])) return false;
  }
  return true;
}

}  // namespace

ClassPointSearch::ClassPointSearch(ModelEvaluator& ev, const FactorGradients& fg, const Box& box,
                                   const std::vector<int>& w_vars, int per_axis,
                                   const PointConstraints* constraints)
    : ev_(ev), fg_(fg), box_(box), u_vars_(chart_complement(ev.model(), w_vars)),
      w_vars_(w_vars), per_axis_(per_axis), pc_(constraints), pt_(box) {
  const int n = ev.n(), p = fg.factors();
  if (pc_ && pc_->atoms) {
    atom_scale_.assign(pc_->which.size(), 1.0);
    if (pc_->atoms->values(ev, box, values_))
      for (size_t k = 0; k < pc_->which.size(); ++k) {
        const Interval& a = values_[pc_->which[k]];
        const double s = std::max(std::fabs(a.lo_down()), std::fabs(a.hi_up()));
        if (s > 0 && std::isfinite(s)) atom_scale_[k] = s;
      }
  }
  // Scales of the factors over the box, to compare their margins with the faces'.
  scale_.assign(p, 1.0);
  if (fg.values(ev, box, values_))
    for (int i = 0; i < p; ++i) {
      const double s = std::max(std::fabs(values_[i].lo_down()), std::fabs(values_[i].hi_up()));
      if (s > 0 && std::isfinite(s)) scale_[i] = s;
    }
  // The grid of u-points: per axis the centres of per_axis equal cells (one point on a
  // degenerate axis).
  std::vector<int> idx(n, 0);
  auto cells = [&](int k) {
    return box[u_vars_[k]].lo_down() == box[u_vars_[k]].hi_up() ? 1 : per_axis;
  };
  for (;;) {
    std::vector<double> u(n);
    for (int k = 0; k < n; ++k) {
      const double lo = box[u_vars_[k]].lo_down(), hi = box[u_vars_[k]].hi_up();
      u[k] = std::min(hi, std::max(lo, lo + (hi - lo) * (idx[k] + 0.5) / cells(k)));
    }
    Sample s;
    if (sample(std::move(u), nullptr, s)) grid_.push_back(std::move(s));
    int k = 0;
    for (; k < n; ++k) {
      if (++idx[k] < cells(k)) break;
      idx[k] = 0;
    }
    if (k == n) break;
  }
}

// The solution over u and its factors; false when Newton fails or a factor is undefined
// there. `face` is negative when w lies outside the box's w-part.
bool ClassPointSearch::sample(std::vector<double> u, const std::vector<double>* start,
                              Sample& out) {
  const int n = ev_.n(), p = fg_.factors();
  for (int k = 0; k < n; ++k) pt_[u_vars_[k]].set_point(u[k]);
  out.u = std::move(u);
  bool ok = newton_w(ev_, pt_, box_, w_vars_, start, out.w);
  if (ok) {
    for (int j = 0; j < n; ++j) pt_[w_vars_[j]].set_point(out.w[j]);
    ok = fg_.values(ev_, pt_, values_);
  }
  if (ok) {
    out.g.resize(p);
    for (int i = 0; i < p; ++i) out.g[i] = values_[i].mid() / scale_[i];
    out.face = INFINITY;
    for (int j = 0; j < n; ++j) {
      const double lo = box_[w_vars_[j]].lo_down(), hi = box_[w_vars_[j]].hi_up();
      if (hi > lo) out.face = std::min(out.face, std::min(out.w[j] - lo, hi - out.w[j]) / (hi - lo));
    }
    if (pc_ && pc_->atoms && !pc_->which.empty()) {
      ok = pc_->atoms->values(ev_, pt_, values_);
      for (size_t k = 0; ok && k < pc_->which.size(); ++k)
        out.face = std::min(out.face, values_[pc_->which[k]].mid() / atom_scale_[k]);
    }
  }
  for (int j = 0; j < n; ++j) pt_[w_vars_[j]] = box_[w_vars_[j]];
  return ok;
}

// The depth of a sample in the piece of class cls: the least of the factors' signed margins
// and the distance to the faces of W; a star centre deep inside has the best chance.
double ClassPointSearch::margin(const Sample& s, uint32_t cls) const {
  double m = s.face;
  for (size_t i = 0; i < s.g.size(); ++i) m = std::min(m, (cls >> i) & 1 ? s.g[i] : -s.g[i]);
  return m;
}

PointVerdict ClassPointSearch::find(uint32_t cls, HsWorkspace& ws, ClassPoint& out) {
  const int n = ev_.n();
  std::vector<const Sample*> found;
  const Sample* best = nullptr;
  for (const Sample& s : grid_) {
    if (margin(s, cls) > 0) found.push_back(&s);
    if (!best || margin(s, cls) > margin(*best, cls)) best = &s;
  }
  std::sort(found.begin(), found.end(),
            [&](const Sample* a, const Sample* b) { return margin(*a, cls) > margin(*b, cls); });
  if (found.size() > 4) found.resize(4);
  for (const Sample* s : found)
    if (prove(*s, cls, ws, out)) return PointVerdict::Found;
  if (!found.empty() || !best) return PointVerdict::NotFound;
  // A piece that is a sliver (the class cut off by a singular surface near a corner of the
  // box) holds no grid point: climb from the deepest one, coordinate by coordinate, with
  // halving steps, towards more depth (Newton from the last w: a short continuation).
  Sample top = *best;
  double top_margin = margin(top, cls);
  std::vector<double> step(n);
  for (int k = 0; k < n; ++k) step[k] = 0.25 * box_[u_vars_[k]].width_up() / per_axis_;
  for (int it = 0; it < 48; ++it) {
    bool moved = false;
    for (int k = 0; k < n; ++k)
      for (double dir : {-1.0, 1.0}) {
        std::vector<double> u = top.u;
        const Interval& axis = box_[u_vars_[k]];
        u[k] = std::min(axis.hi_up(), std::max(axis.lo_down(), u[k] + dir * step[k]));
        Sample c;
        if (u[k] == top.u[k] || !sample(std::move(u), &top.w, c)) continue;
        const double cm = margin(c, cls);
        if (cm > top_margin) top = std::move(c), top_margin = cm, moved = true;
      }
    if (!moved)
      for (double& h : step) h *= 0.5;
    if (top_margin > 0 && !moved) break;
  }
  if (top_margin > 0 && prove(top, cls, ws, out)) return PointVerdict::Found;
  return PointVerdict::NotFound;
}

// Iteration (9) at the u-point, its enclosure inside the box's W, every factor of sign s_i.
bool ClassPointSearch::prove(const Sample& s, uint32_t cls, HsWorkspace& ws, ClassPoint& out) {
  const int n = ev_.n(), p = fg_.factors();
  Box z = box_;
  for (int k = 0; k < n; ++k) z[u_vars_[k]].set_point(s.u[k]);
  for (int j = 0; j < n; ++j) {
    const double r = 1e-12 * (1 + std::fabs(s.w[j]));
    z[w_vars_[j]].set_hull(s.w[j] - r, s.w[j] + r);
  }
  ExistenceProof proof;
  if (prove_existence(ev_, z, 1.01, 12, proof, ws, false, nullptr, &w_vars_) != Existence::Proved)
    return false;
  for (int j = 0; j < n; ++j) {
    if (!box_[w_vars_[j]].contains(proof.image[j])) return false;
    z[w_vars_[j]] = proof.image[j];
  }
  if (!fg_.values(ev_, z, values_)) return false;
  for (int i = 0; i < p; ++i) {
    const bool positive = (cls >> i) & 1;
    if (!(positive ? values_[i].certainly_pos() : values_[i].certainly_neg())) return false;
  }
  // A feasible point: every constraint True on it (the atoms True on the box among them).
  if (pc_ && pc_->check && pc_->check->evaluate(z) != Truth::True) return false;
  out.u_vars = u_vars_;
  out.w_vars = w_vars_;
  out.u = s.u;
  out.w = proof.image;
  return true;
}

PointVerdict find_class_point(ModelEvaluator& ev, const FactorGradients& fg, const Box& box,
                              const std::vector<int>& w, uint32_t cls, HsWorkspace& ws,
                              ClassPoint& out, int per_axis,
                              const PointConstraints* constraints) {
  return ClassPointSearch(ev, fg, box, w, per_axis, constraints).find(cls, ws, out);
}

}  // namespace aspects
