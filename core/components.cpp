#include "components.h"

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>
#include <numeric>

namespace aspects {

Components connected_components(int n, const std::vector<std::pair<int32_t, int32_t>>& edges) {
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
  Graph g(n);
  for (const auto& e : edges) boost::add_edge(e.first, e.second, g);
  std::vector<int> comp(n);
  int count = n ? boost::connected_components(g, comp.data()) : 0;
  std::vector<int64_t> size(count, 0);
  std::vector<int> first(count, n);
  for (int v = 0; v < n; ++v) {
    ++size[comp[v]];
    first[comp[v]] = std::min(first[comp[v]], v);
  }
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return size[a] != size[b] ? size[a] > size[b] : first[a] < first[b];
  });
  std::vector<int> rank(count);
  Components out;
  for (int i = 0; i < count; ++i) {
    rank[order[i]] = i;
    out.sizes.push_back(size[order[i]]);
  }
  out.of.resize(n);
  for (int v = 0; v < n; ++v) out.of[v] = rank[comp[v]];
  return out;
}

int filter_components(const std::vector<int64_t>& sizes, double min_ratio) {
  if (sizes.size() <= 1) return int(sizes.size());
  double best = 0;
  int cut = int(sizes.size());
  for (size_t i = 0; i + 1 < sizes.size(); ++i) {
    double r = double(sizes[i]) / double(sizes[i + 1]);
    if (r > best) {
      best = r;
      cut = int(i) + 1;
    }
  }
  return best < min_ratio ? int(sizes.size()) : cut;
}

}  // namespace aspects
