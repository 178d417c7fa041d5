#include "counting/chart.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace aspects {

std::vector<int> chart_complement(const Model& m, const std::vector<int>& w) {
  std::vector<int> u;
  for (int v = 0; v < int(m.vars.size()); ++v)
    if (std::find(w.begin(), w.end(), v) == w.end()) u.push_back(v);
  return u;
}

std::vector<std::vector<int>> chart_candidates(ModelEvaluator& ev, const Box& box, int mixed) {
  const Model& m = ev.model();
  const int n = m.n(), nv = int(m.vars.size());
  std::vector<std::vector<int>> out{m.command, m.pose};
  if (mixed <= 0) return out;
  // [Fx Fq] at the middle of the box, columns in model order.
  Box mid = box;
  for (auto& x : mid) x.set_point(x.mid());
  IMatrix Jx, Jq;
  if (ev.jacobian_x(mid, Jx) != EvalStatus::Defined || ev.jacobian_q(mid, Jq) != EvalStatus::Defined)
    return out;
  Eigen::MatrixXd J(n, nv);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) J(i, m.pose[j]) = Jx(i, j).mid();
    for (int j = 0; j < n; ++j) J(i, m.command[j]) = Jq(i, j).mid();
  }
  // Every n-subset but the two above, scored by |det| over the product of column norms.
  std::vector<std::pair<double, std::vector<int>>> scored;
  std::vector<int> pick(nv, 0);
  std::fill(pick.end() - n, pick.end(), 1);
  do {
    std::vector<int> w;
    for (int v = 0; v < nv; ++v)
      if (pick[v]) w.push_back(v);
    if (w == m.command || w == m.pose) continue;
    Eigen::MatrixXd A(n, n);
    double norms = 1;
    for (int j = 0; j < n; ++j) {
      A.col(j) = J.col(w[j]);
      norms *= std::max(A.col(j).norm(), 1e-300);
    }
    const double score = std::fabs(A.determinant()) / norms;
    if (std::isfinite(score) && score > 1e-6) scored.push_back({score, w});
  } while (std::next_permutation(pick.begin(), pick.end()));
  std::sort(scored.begin(), scored.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  for (int k = 0; k < mixed && k < int(scored.size()); ++k) out.push_back(scored[k].second);
  return out;
}

int chart_split_variable(ModelEvaluator& ev, const Box& box, const std::vector<double>& scale) {
  const Model& m = ev.model();
  const int n = m.n(), nv = int(m.vars.size());
  Box mid = box;
  for (auto& x : mid) x.set_point(x.mid());
  IMatrix Jx, Jq;
  if (ev.jacobian_x(mid, Jx) != EvalStatus::Defined || ev.jacobian_q(mid, Jq) != EvalStatus::Defined)
    return -1;
  Eigen::MatrixXd J(n, nv);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) J(i, m.pose[j]) = Jx(i, j).mid();
    for (int j = 0; j < n; ++j) J(i, m.command[j]) = Jq(i, j).mid();
  }
  double best_size = INFINITY;
  int best_var = -1;
  for (const std::vector<int>& w : chart_candidates(ev, box, nv)) {
    const std::vector<int> u = chart_complement(m, w);
    Eigen::MatrixXd Jw(n, n), Ju(n, n);
    for (int j = 0; j < n; ++j) Jw.col(j) = J.col(w[j]), Ju.col(j) = J.col(u[j]);
    Eigen::FullPivLU<Eigen::MatrixXd> lu(Jw);
    if (!lu.isInvertible()) continue;
    const Eigen::MatrixXd X = lu.solve(Ju);
    if (!X.allFinite()) continue;
    // The box U × r in relative widths, and each u_k's share of it.
    double size = 0;
    std::vector<double> share(n, 0);
    for (int k = 0; k < n; ++k) {
      const double uk = box[u[k]].width_up();
      share[k] = uk / scale[u[k]];
      size = std::max(size, share[k]);
    }
    for (int j = 0; j < n; ++j) {
      double r = 0;
      for (int k = 0; k < n; ++k) {
        const double c = std::fabs(X(j, k)) * box[u[k]].width_up() / scale[w[j]];
        r += c;
        share[k] = std::max(share[k], c);
      }
      size = std::max(size, r);
    }
    if (size < best_size) {
      best_size = size;
      best_var = u[std::max_element(share.begin(), share.end()) - share.begin()];
    }
  }
  return best_var;
}

ChartVerdict prove_chart(ModelEvaluator& ev, const Box& box, const std::vector<int>& w,
                         HsWorkspace& ws, Chart& chart) {
  const int n = ev.n();
  chart.w = w;
  chart.u = chart_complement(ev.model(), w);
  std::vector<Interval> image;
  if (hansen_sengupta(ev, box, true, image, ws, false, &chart.w) == HsStatus::NoSolution)
    return ChartVerdict::NoSolution;
  // Iteration (9) with W̃ always holding the box's W: uniqueness must hold there for the
  // graph to hold every solution of the box, and the graph may leave W through a face (a box
  // cut across the solution set), so the image can stick out of W on one side and be
  // narrower on another. [Plain ε-inflation of the image would lose the box's W.]
  Box work = box;
  std::vector<Interval> y;
  double first_width = 0;  // of the first image: the graph's range over U, roughly
  for (int k = 0; k < 8; ++k) {
    for (int j = 0; j < n; ++j) {
      Interval& q = work[w[j]];
      const double mid = q.mid(), lo = q.lo_down(), hi = q.hi_up();
      double nlo = std::nextafter(std::min(mid - 1.01 * (mid - lo), lo), -INFINITY);
      double nhi = std::nextafter(std::max(mid + 1.01 * (hi - mid), hi), INFINITY);
      nlo = std::min(nlo, box[w[j]].lo_down());
      nhi = std::max(nhi, box[w[j]].hi_up());
      q.set_hull(nlo, nhi);
    }
    if (hansen_sengupta(ev, work, false, y, ws, false, &chart.w) != HsStatus::Ok)
      return ChartVerdict::NotProved;
    bool inside = true;
    double width = 0;
    for (int j = 0; j < n; ++j) {
      round_out_to_doubles(y[j]);
      inside = inside && work[w[j]].strictly_contains(y[j]);
      width = std::max(width, y[j].width_up());
    }
    if (inside) {
      chart.w_range = y;
      chart.w_tilde.clear();
      for (int j = 0; j < n; ++j) chart.w_tilde.push_back(work[w[j]]);
      return ChartVerdict::Proved;
    }
    if (k == 0) first_width = width;
    // Diverging. (Not against the box's W: a box cut across the graph is narrower than its
    // range over U, and the iteration is meant to reach that range.)
    if (!(width <= 4 * first_width)) return ChartVerdict::NotProved;
    for (int j = 0; j < n; ++j) work[w[j]] = y[j];
  }
  return ChartVerdict::NotProved;
}

}  // namespace aspects
