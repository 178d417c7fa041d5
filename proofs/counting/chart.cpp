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

ChartVerdict prove_chart(ModelEvaluator& ev, const Box& box, const std::vector<int>& w,
                         HsWorkspace& ws, Chart& chart) {
  const int n = ev.n();
  chart.w = w;
  chart.u = chart_complement(ev.model(), w);
  std::vector<Interval> image;
  if (hansen_sengupta(ev, box, true, image, ws, false, &chart.w) == HsStatus::NoSolution)
    return ChartVerdict::NoSolution;
  ExistenceProof proof;
  if (prove_existence(ev, box, 1.01, 8, proof, ws, false, nullptr, &chart.w) != Existence::Proved)
    return ChartVerdict::NotProved;
  // Uniqueness holds in W̃: it must hold the box's W for the graph to hold every solution.
  for (int j = 0; j < n; ++j)
    if (!proof.inflated[j].contains(box[chart.w[j]])) return ChartVerdict::NotProved;
  chart.w_range = proof.image;
  return ChartVerdict::Proved;
}

}  // namespace aspects
