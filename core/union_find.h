// Disjoint sets over 0..n-1 with path halving and union by size: the connectivity the
// link phase already knows, so that it proves only links that join two components.
#pragma once

#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace aspects {

class UnionFind {
 public:
  explicit UnionFind(size_t n = 0) : parent_(n), size_(n, 1) {
    std::iota(parent_.begin(), parent_.end(), int32_t(0));
  }
  int32_t find(int32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  // find() without path halving: safe for concurrent readers (depth is O(log n)).
  int32_t root(int32_t x) const {
    while (parent_[x] != x) x = parent_[x];
    return x;
  }
  // False when a and b were already in one set.
  bool unite(int32_t a, int32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    return true;
  }

 private:
  std::vector<int32_t> parent_;
  std::vector<int32_t> size_;
};

}  // namespace aspects
