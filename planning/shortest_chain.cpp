#include "shortest_chain.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "results/pose.h"

namespace aspects {

namespace {

std::vector<double> pose_centre(const LoadedResult& r, size_t i) {
  const IndexSolutionBox& s = r.index.solutions[i];
  std::vector<double> c;
  for (int v : r.model.pose) c.push_back(0.5 * s.lo[v] + 0.5 * s.hi[v]);
  return c;
}

// The middle of a ∩ (b + 2πk) on the pose, in a's frame (a weight only).
std::vector<double> common_middle(const LoadedResult& r, size_t a, size_t b, uint32_t code) {
  const IndexSolutionBox& sa = r.index.solutions[a];
  const IndexSolutionBox& sb = r.index.solutions[b];
  std::vector<double> w;
  for (int v : r.model.pose) {
    const double s = 2 * M_PI * (int((code >> (2 * v)) & 3u) - 1);
    w.push_back(0.5 * std::max(sa.lo[v], sb.lo[v] + s) + 0.5 * std::min(sa.hi[v], sb.hi[v] + s));
  }
  return w;
}

enum class EdgeState : char { Unknown, Proved, Failed };

}  // namespace

bool shortest_chain(const LoadedResult& r, CsncLinks& links, const std::vector<double>& from,
                    const std::vector<double>& to, const std::vector<size_t>& from_boxes,
                    const std::vector<size_t>& to_boxes, Chain& chain) {
  const std::vector<bool>& per = r.pose_periodic;
  const size_t nsol = r.index.solutions.size();
  std::vector<std::vector<double>> centre(nsol);
  std::vector<double> heuristic(nsol, 0);
  for (size_t i : links.boxes()) {
    centre[i] = pose_centre(r, i);
    heuristic[i] = pose_distance(centre[i], to, per);  // admissible: every chain goes there
  }
  std::vector<char> is_goal(nsol, 0);
  for (size_t i : to_boxes)
    if (r.index.solutions[i].csnc == links.csnc()) is_goal[i] = 1;
  std::vector<std::vector<EdgeState>> state(nsol);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (;;) {
    // A* from the start pose (edges to each box holding it) to the goal pose.
    std::vector<double> dist(nsol, kInf);
    std::vector<std::pair<size_t, size_t>> pred(nsol, {SIZE_MAX, 0});  // (box, neighbour #)
    std::vector<char> done(nsol, 0);
    using Item = std::pair<double, size_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
    for (size_t i : from_boxes) {
      if (r.index.solutions[i].csnc != links.csnc()) continue;
      const double g = pose_distance(from, centre[i], per);
      if (g < dist[i]) dist[i] = g, open.push({g + heuristic[i], i});
    }
    size_t reached = SIZE_MAX;
    double best = kInf;  // start → ... → box → goal pose
    while (!open.empty()) {
      const auto [f, u] = open.top();
      open.pop();
      if (done[u]) continue;
      if (f >= best) break;
      done[u] = 1;
      if (is_goal[u]) {
        const double total = dist[u] + pose_distance(centre[u], to, per);
        if (total < best) best = total, reached = u;
      }
      const std::vector<BoxNeighbor>& nbs = links.neighbors(u);
      if (state[u].size() != nbs.size()) state[u].assign(nbs.size(), EdgeState::Unknown);
      for (size_t e = 0; e < nbs.size(); ++e) {
        if (state[u][e] == EdgeState::Failed) continue;
        const size_t v = nbs[e].other;
        const std::vector<double> w = common_middle(r, u, v, nbs[e].shift_code);
        const double g = dist[u] + pose_distance(centre[u], w, per) + pose_distance(w, centre[v], per);
        if (g < dist[v]) {
          dist[v] = g;
          pred[v] = {u, e};
          open.push({g + heuristic[v], v});
        }
      }
    }
    if (reached == SIZE_MAX) return false;
    std::vector<size_t> boxes{reached};
    std::vector<std::pair<size_t, size_t>> edges;
    for (size_t v = reached; pred[v].first != SIZE_MAX; v = pred[v].first) {
      edges.push_back(pred[v]);
      boxes.push_back(pred[v].first);
    }
    std::reverse(boxes.begin(), boxes.end());
    std::reverse(edges.begin(), edges.end());
    bool all = true;
    chain.boxes = boxes;
    chain.links.clear();
    for (const auto& [u, e] : edges) {
      const BoxNeighbor& nb = links.neighbors(u)[e];
      const LinkProof* proof = links.link(u, nb.other, nb.shift_code);
      state[u][e] = proof ? EdgeState::Proved : EdgeState::Failed;
      all = all && proof;
      chain.links.push_back({u, nb.other, nb.shift_code, proof});
    }
    if (all) return true;
  }
}

}  // namespace aspects
