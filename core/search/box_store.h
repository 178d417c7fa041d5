// Compact storage of many boxes with double endpoints (2·nv doubles per box). Boxes
// stored here are exact: every box the engine reports has double endpoints.
#pragma once

#include <vector>

#include "numerics/interval.h"

namespace aspects {

class BoxStore {
 public:
  explicit BoxStore(int nv = 0) : nv_(nv) {}
  int nv() const { return nv_; }
  int size() const { return nv_ ? int(coords_.size() / (2 * size_t(nv_))) : 0; }
  double lo(int i, int v) const { return coords_[(size_t(i) * nv_ + v) * 2]; }
  double hi(int i, int v) const { return coords_[(size_t(i) * nv_ + v) * 2 + 1]; }
  int push(const Box& b) {
    for (const auto& x : b) {
      coords_.push_back(x.lo_down());
      coords_.push_back(x.hi_up());
    }
    return size() - 1;
  }
  // Box i of `from` (same nv), copied exactly.
  int push_copy(const BoxStore& from, int i) {
    const double* p = &from.coords_[size_t(i) * 2 * nv_];
    coords_.insert(coords_.end(), p, p + 2 * size_t(nv_));
    return size() - 1;
  }
  void reserve(size_t boxes) { coords_.reserve(boxes * 2 * size_t(nv_)); }
  void release() { std::vector<double>().swap(coords_); }  // empty, memory returned
  // The endpoints, box after box (lo, hi per variable): for checkpoints.
  const std::vector<double>& coords() const { return coords_; }
  void append_coords(const double* lohi, size_t boxes) {
    coords_.insert(coords_.end(), lohi, lohi + boxes * 2 * size_t(nv_));
  }
  void get(int i, Box& b) const {
    b.resize(nv_);
    for (int v = 0; v < nv_; ++v) b[v].set_hull(lo(i, v), hi(i, v));
  }

 private:
  int nv_;
  std::vector<double> coords_;
};

}  // namespace aspects
