// Neighbourhood graph (R, M) of paper 4.3.1: two output boxes are neighbours when they
// may share a point, modulo 2π on periodic variables. M is exactly the graph that
// certificates/FORMAT.md defines ("claim lower-bound"; shifted ends rounded outward), so
// the solver's bound is the one check_cert recomputes: missing pairs would be unsound,
// extra ones would make the two bounds differ. The search uses the hulls of the output
// boxes below each tree node (a bounding-volume hierarchy over the bisection tree).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "aspects/for_each_index.h"

#include "search/box_store.h"
#include "search/branch_and_prune.h"

namespace aspects {

struct NeighborPair {
  int32_t a, b;  // output box ids, a < b
  // Per variable v, k_v ∈ {-1, 0, 1} packed in 2 bits: box b shifted by 2π·k meets a.
  uint32_t shift_code = 0;
  int shift(int v) const { return int((shift_code >> (2 * v)) & 3u) - 1; }
};

// Packs a shift vector (at most 16 variables).
uint32_t pack_shift(const std::vector<int>& k);

// M sorted by (a, b), each pair once, a piece at a time so that it need not be held whole
// (479 M pairs, 5.8 GB, on 3-RPR at eps 0.3): the boxes are queried in blocks, a round of
// blocks at once through `for_each`, then `consume` receives each block's pairs in order on
// the calling thread. The pieces do not depend on `for_each`. `stop` is asked before each
// round; once it says stop, the stream ends there and returns false (M was not all given).
bool stream_neighbor_pairs(const std::vector<SearchNode>& tree, const BoxStore& R,
                           const std::vector<bool>& periodic,
                           const std::function<void(const std::vector<NeighborPair>&)>& consume,
                           const ForEachIndex& for_each = serial_for_each,
                           const std::function<bool()>& stop = {});

// All of M, concatenated.
std::vector<NeighborPair> neighbor_pairs(const std::vector<SearchNode>& tree, const BoxStore& R,
                                         const std::vector<bool>& periodic,
                                         const ForEachIndex& for_each = serial_for_each);

}  // namespace aspects
