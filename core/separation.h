// Paper 4.4.2: separation by the signs of the determinant factors d1..dp.
// For each s ∈ {−1,1}^p, R^s holds the boxes whose enclosures of s_i·d_i are not
// certainly negative; (R^s, M^s) is split into connected components. A component
// counts toward the bound (11) when it holds a certified box whose factor enclosures
// all certainly have the signs s (a box whose enclosure straddles 0 counts in no class).
// Since every aspect has constant signs and lies in one component of one R^s (the
// boxes R cover every solution), distinct counted components hold distinct aspects.
#pragma once

#include <cstdint>
#include <vector>

#include "neighborhood_graph.h"

namespace aspects {

struct SeparationResult {
  int lower_bound = 0;
  std::vector<int> per_class;  // counted components per sign vector (bit i set: s_i = +1)
  // For each counted component, the largest CSNC among its certified boxes of that sign
  // class (when CSNCs are given): CSNCs certified to lie in pairwise distinct aspects.
  std::vector<int32_t> representatives;
};

// signs: p entries per box (−1, 0 = may vanish, +1); certified: 1 for solution boxes.
// csnc (optional): component of each box by decreasing size (-1 for none).
SeparationResult separate_by_signs(int boxes, int p, const std::vector<int8_t>& signs,
                                   const std::vector<uint8_t>& certified,
                                   const std::vector<NeighborPair>& M,
                                   const std::vector<int32_t>* csnc = nullptr);

}  // namespace aspects
