// The output boxes R = S ∪ U of a search (paper 4.2), in output order: each box's ends,
// whether it is a certified solution box, why an undecided box stayed undecided, and the
// sign of each determinant factor on it (paper 4.4.2). One store owns all four, so they
// cannot fall out of step; each phase after the search reads it.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "numerics/interval.h"
#include "search/box_store.h"

namespace aspects {

enum class UndecidedKind : uint8_t {
  NoExistence = 0,  // P1 not proved (red in the paper's figures)
  Singular = 1,     // P1 proved, P2 not (black)
  Constraint = 2,   // on the boundary of an additional constraint (blue, paper 5.4)
  Unexplored = 3,   // the search stopped before this cell: not a verdict at all
};

class OutputBoxes {
 public:
  // `factors`: the signs kept per box (p, the number of determinant factors).
  explicit OutputBoxes(int nv = 0, int factors = 0) : ends_(nv), p_(factors) {}

  int size() const { return ends_.size(); }
  int nv() const { return ends_.nv(); }
  int factors() const { return p_; }
  const BoxStore& ends() const { return ends_; }
  double lo(int i, int v) const { return ends_.lo(i, v); }
  double hi(int i, int v) const { return ends_.hi(i, v); }
  void get(int i, Box& b) const { ends_.get(i, b); }

  bool certified(int i) const { return certified_[i] != 0; }
  // NoExistence for a solution box (the kind says nothing there).
  UndecidedKind kind(int i) const { return kind_[i]; }
  bool unexplored(int i) const { return kind_[i] == UndecidedKind::Unexplored; }
  // The p signs of box i: +1 or −1 where the factor's enclosure clears 0, else 0.
  const int8_t* signs(int i) const { return signs_.data() + size_t(i) * p_; }

  // Appends a box (its ends rounded outward to doubles) with its signs; its index.
  int32_t push(const Box& box, bool certified, UndecidedKind kind, const int8_t* signs) {
    int32_t i = ends_.push(box);
    certified_.push_back(certified);
    kind_.push_back(kind);
    signs_.insert(signs_.end(), signs, signs + p_);
    return i;
  }
  // Box i of `from` (same nv and p), copied exactly.
  int32_t push_copy(const OutputBoxes& from, int i) {
    int32_t j = ends_.push_copy(from.ends_, i);
    certified_.push_back(from.certified_[i]);
    kind_.push_back(from.kind_[i]);
    signs_.insert(signs_.end(), from.signs(i), from.signs(i) + p_);
    return j;
  }
  void reserve(size_t boxes) {
    ends_.reserve(boxes);
    certified_.reserve(boxes);
    kind_.reserve(boxes);
    signs_.reserve(boxes * p_);
  }
  void release() {  // empty, memory returned
    ends_.release();
    std::vector<uint8_t>().swap(certified_);
    std::vector<UndecidedKind>().swap(kind_);
    std::vector<int8_t>().swap(signs_);
  }

  // The columns whole, box after box: for the separation's passes and for checkpoints.
  const std::vector<uint8_t>& certified_column() const { return certified_; }
  const std::vector<UndecidedKind>& kind_column() const { return kind_; }
  const std::vector<int8_t>& sign_column() const { return signs_; }
  // A store from its columns (a checkpoint read back); throws std::invalid_argument when
  // their lengths disagree.
  static OutputBoxes from_columns(int nv, int factors, const std::vector<double>& lohi,
                                  std::vector<uint8_t> certified, std::vector<UndecidedKind> kind,
                                  std::vector<int8_t> signs) {
    OutputBoxes r(nv, factors);
    const size_t boxes = certified.size();
    if (lohi.size() != boxes * 2 * size_t(nv) || kind.size() != boxes ||
        signs.size() != boxes * size_t(factors))
      throw std::invalid_argument("output boxes: columns of different lengths");
    r.ends_.append_coords(lohi.data(), boxes);
    r.certified_ = std::move(certified);
    r.kind_ = std::move(kind);
    r.signs_ = std::move(signs);
    return r;
  }

 private:
  BoxStore ends_;
  int p_;
  std::vector<uint8_t> certified_;
  std::vector<UndecidedKind> kind_;
  std::vector<int8_t> signs_;  // p_ per box
};

}  // namespace aspects
