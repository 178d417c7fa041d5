#include "aspects/components.h"

#include <algorithm>
#include <boost/pending/disjoint_sets.hpp>
#include <numeric>

namespace aspects {

Components connected_components(int n, const std::vector<std::pair<int32_t, int32_t>>& edges) {
  // Boost's union-find (that of Boost.Graph's incremental components) over the edges:
  // 5 bytes per vertex, where an adjacency_list takes about 100 per vertex and edge.
  std::vector<uint8_t> ranks(n);  // below log2(n)
  std::vector<int> parent(n);
  boost::disjoint_sets<uint8_t*, int*> sets(ranks.data(), parent.data());
  for (int v = 0; v < n; ++v) sets.make_set(v);
  for (const auto& e : edges) sets.union_set(e.first, e.second);
  // Components numbered by their roots' first appearance (renumbered by size below).
  std::vector<int> comp(n), id(n, -1);
  int count = 0;
  for (int v = 0; v < n; ++v) {
    int& r = id[sets.find_set(v)];
    if (r < 0) r = count++;
    comp[v] = r;
  }
  std::vector<int>().swap(id);
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
