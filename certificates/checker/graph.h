// graph.h — the combinatorial half of the check: a union-find, the neighbourhood graph M
// of FORMAT.md ("claim lower-bound") built by sort-and-sweep over the output boxes and
// their 2π-shifted copies, the separated lower bound (11), and the filtering heuristic.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "ival.h"

namespace cc {

struct UnionFind {
  std::vector<int> parent;
  void reset(size_t n);
  int find(int x);
  void unite(int a, int b);
};

// Output boxes kept compactly as doubles, with their verified factor signs.
struct OutBoxes {
  int nv = 0;
  std::vector<double> lohi;    // 2·nv per box
  std::vector<uint32_t> pos, neg;  // bit i: factor i verified > 0 (resp. < 0)
  std::vector<uint8_t> solution;
  size_t size() const { return solution.size(); }
  const double* box(size_t i) const { return &lohi[i * 2 * nv]; }
};

// t := x + 2πk in MPFI: the bound x of a box shifted by k periods. Its ends rounded outward
// (graph M) or inward (links) to doubles give the shifted bound each check needs.
void shift_by_periods(Ival& t, const Ival& two_pi, int k, double x);

// Pairs (a, b), a < b, such that for some shift k (k_v ∈ {−1, 0, 1} on periodic variables)
// a meets b + 2πk with the shifted bounds rounded outward; a superset of the pairs that
// share a point modulo 2π. Throws std::length_error beyond `max_pairs` pairs: boxes that
// all overlap (one IMAGE for many cells) would make M quadratic in memory.
std::vector<std::pair<int, int>> neighbour_pairs(const OutBoxes& R,
                                                 const std::vector<bool>& periodic,
                                                 const Ival& two_pi, size_t max_pairs = SIZE_MAX);
// Bound (11): Σ over sign vectors s of the number of components (of the boxes compatible
// with s, joined by M) holding a solution box whose signs are all verified and equal s.
// Only the factors whose bit is set in `use` separate (the others are ignored). Throws
// std::length_error when classes × (pairs + boxes) exceeds 2^32.
long lower_bound(const OutBoxes& R, const std::vector<std::pair<int, int>>& M, uint32_t use);
// Filtering: cut at the largest ratio of consecutive sizes; keep all if it is < 2.
long filtered_count(const std::vector<int64_t>& sizes);

}  // namespace cc
