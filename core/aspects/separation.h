// Paper 4.4.2: separation by the signs of the determinant factors d1..dp.
// For each s ∈ {−1,1}^p, R^s holds the boxes whose enclosures of s_i·d_i are not
// certainly negative; (R^s, M^s) is split into connected components. A component
// counts toward the bound (11) when it holds a certified box whose factor enclosures
// all certainly have the signs s (a box whose enclosure straddles 0 counts in no class).
// Since every aspect has constant signs and lies in one component of one R^s (the
// boxes R cover every solution), distinct counted components hold distinct aspects.
#pragma once

#include <boost/pending/disjoint_sets.hpp>

#include <cstdint>
#include <vector>

#include "aspects/for_each_index.h"
#include "aspects/neighborhood_graph.h"

namespace aspects {

struct SeparationResult {
  int lower_bound = 0;
  std::vector<int> per_class;  // counted components per sign vector (bit i set: s_i = +1)
  // For each counted component, the largest CSNC among its certified boxes of that sign
  // class (when CSNCs are given): CSNCs certified to lie in pairwise distinct aspects.
  std::vector<int32_t> representatives;
};

// The components of every (R^s, M^s) for a list of classes s, fed M a piece at a time in
// any order (union–find does not depend on it), so that M need never be held whole: on
// 3-RPR at eps 0.3 it is 479 M pairs, 5.8 GB.
class SignSeparation {
 public:
  // The classes that can count, increasing: those of the certified boxes whose factors all
  // have a certain sign (the others count nothing). On 3-RPR, 2 of 16: three of its four
  // factors, −2 q_i with q_i ≥ 10, have a fixed sign.
  static std::vector<uint32_t> counting_classes(int boxes, int p, const std::vector<int8_t>& signs,
                                                const std::vector<uint8_t>& certified);
  // signs: p entries per box (−1, 0 = may vanish, +1). Keeps a reference to `signs`.
  // A forest over all boxes per class of `classes`: 5 bytes per box and class.
  SignSeparation(int boxes, int p, const std::vector<int8_t>& signs,
                 std::vector<uint32_t> classes);
  // Joins the pairs' boxes in every class holding both; the classes run through `for_each`.
  void add(const std::vector<NeighborPair>& pairs, const ForEachIndex& for_each = serial_for_each);
  // certified: 1 for solution boxes; csnc (optional): component of each box by decreasing
  // size (-1 for none). Counts for this object's classes only (per_class: 0 for others).
  SeparationResult result(const std::vector<uint8_t>& certified,
                          const std::vector<int32_t>* csnc = nullptr);

 private:
  bool compatible(uint32_t s, int32_t b) const;
  bool exact(uint32_t s, int32_t b) const;
  using Forest = boost::disjoint_sets<uint8_t*, int32_t*>;
  Forest forest(size_t c);
  int boxes_, p_;
  const std::vector<int8_t>& signs_;
  std::vector<uint32_t> classes_;
  // Per class of classes_, the forest's arrays: ranks in a byte (they stay below
  // log2 of the box count), 5 bytes per box.
  std::vector<std::vector<int32_t>> parent_;
  std::vector<std::vector<uint8_t>> rank_;
};

// Adds the counts of other classes (from another SignSeparation) to `total`.
void merge_separation(SeparationResult& total, const SeparationResult& part);

// The whole computation on a listed M.
SeparationResult separate_by_signs(int boxes, int p, const std::vector<int8_t>& signs,
                                   const std::vector<uint8_t>& certified,
                                   const std::vector<NeighborPair>& M,
                                   const std::vector<int32_t>* csnc = nullptr);

}  // namespace aspects
