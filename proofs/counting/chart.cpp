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

namespace {

// [Fx Fq] at the middle of the box, columns in model order; false if undefined there.
bool middle_jacobian(ModelEvaluator& ev, const Box& box, Eigen::MatrixXd& J) {
  const Model& m = ev.model();
  const int n = m.n();
  Box mid = box;
  for (auto& x : mid) x.set_point(x.mid());
  IMatrix Jx, Jq;
  if (ev.jacobian_x(mid, Jx) != EvalStatus::Defined || ev.jacobian_q(mid, Jq) != EvalStatus::Defined)
    return false;
  J.resize(n, int(m.vars.size()));
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) J(i, m.pose[j]) = Jx(i, j).mid();
    for (int j = 0; j < n; ++j) J(i, m.command[j]) = Jq(i, j).mid();
  }
  return J.allFinite();
}

struct ChartGuess {
  std::vector<int> w;
  double size;  // of U × (W ∪ r), each width over its scale
  int cut;      // where to bisect when no chart holds
};

// Every chart whose ∂_w f is regular at the middle, smallest predicted box first.
std::vector<ChartGuess> rank_charts(ModelEvaluator& ev, const Box& box,
                                    const std::vector<double>& scale) {
  const Model& m = ev.model();
  const int n = m.n(), nv = int(m.vars.size());
  std::vector<ChartGuess> out;
  Eigen::MatrixXd J;
  if (!middle_jacobian(ev, box, J)) return out;
  std::vector<int> pick(nv, 0);
  std::fill(pick.end() - n, pick.end(), 1);
  do {
    ChartGuess g;
    for (int v = 0; v < nv; ++v)
      if (pick[v]) g.w.push_back(v);
    const std::vector<int> u = chart_complement(m, g.w);
    Eigen::MatrixXd Jw(n, n), Ju(n, n);
    for (int j = 0; j < n; ++j) Jw.col(j) = J.col(g.w[j]), Ju.col(j) = J.col(u[j]);
    Eigen::FullPivLU<Eigen::MatrixXd> lu(Jw);
    if (!lu.isInvertible()) continue;
    const Eigen::MatrixXd X = lu.solve(Ju);
    if (!X.allFinite()) continue;
    // The proof works on U × (W ∪ r): a w-part much wider than the graph's range r is cut
    // (the halves then contract around the graph), else the u_k that adds most to r.
    std::vector<double> share(n, 0);
    g.size = 0;
    for (int k = 0; k < n; ++k) {
      share[k] = box[u[k]].width_up() / scale[u[k]];
      g.size = std::max(g.size, share[k]);
    }
    double widest_w = 0;
    int wide_w = -1;
    for (int j = 0; j < n; ++j) {
      double r = 0;
      for (int k = 0; k < n; ++k) {
        const double c = std::fabs(X(j, k)) * box[u[k]].width_up() / scale[g.w[j]];
        r += c;
        share[k] = std::max(share[k], c);
      }
      const double wj = box[g.w[j]].width_up() / scale[g.w[j]];
      g.size = std::max(g.size, std::max(r, wj));
      if (wj > 2 * r && wj > widest_w) widest_w = wj, wide_w = g.w[j];
    }
    if (!std::isfinite(g.size)) continue;
    const int k = int(std::max_element(share.begin(), share.end()) - share.begin());
    g.cut = wide_w >= 0 && widest_w > share[k] ? wide_w : u[k];
    out.push_back(std::move(g));
  } while (std::next_permutation(pick.begin(), pick.end()));
  std::stable_sort(out.begin(), out.end(),
                   [](const ChartGuess& a, const ChartGuess& b) { return a.size < b.size; });
  return out;
}

}  // namespace

std::vector<std::vector<int>> chart_candidates(ModelEvaluator& ev, const Box& box,
                                               const std::vector<double>& scale, int limit) {
  std::vector<std::vector<int>> out;
  for (ChartGuess& g : rank_charts(ev, box, scale)) {
    if (int(out.size()) >= limit) break;
    out.push_back(std::move(g.w));
  }
  // Undefined or singular at the middle: the proof may still hold on the box.
  if (out.empty()) out = {ev.model().command, ev.model().pose};
  return out;
}

int chart_split_variable(ModelEvaluator& ev, const Box& box, const std::vector<double>& scale) {
  const std::vector<ChartGuess> ranked = rank_charts(ev, box, scale);
  return ranked.empty() ? -1 : ranked.front().cut;
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
