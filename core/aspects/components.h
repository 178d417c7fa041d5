// Paper 4.4.1: CSNCs are the connected components of the certified graph (S, N),
// computed with Boost's disjoint sets (Boost.Graph's union-find); then the filtering
// heuristic.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace aspects {

struct Components {
  std::vector<int32_t> of;    // component of each vertex, numbered by decreasing size
  std::vector<int64_t> sizes; // vertex count per component, largest first
};

// Connected components of an undirected graph on `n` vertices; components are
// renumbered by decreasing size (ties: smallest first vertex first).
Components connected_components(int n, const std::vector<std::pair<int32_t, int32_t>>& edges);

// Filtering heuristic (4.4.1): with sizes sorted decreasingly, cut after the largest
// ratio s_i / s_{i+1}. Tie rule: when that ratio is below `min_ratio` (symmetric robots
// have components of equal size), every component is kept. Returns how many are kept.
// A heuristic: it decides what is shown, never what is certified.
int filter_components(const std::vector<int64_t>& sizes, double min_ratio = 2.0);

}  // namespace aspects
