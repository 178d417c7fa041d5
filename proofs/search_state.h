// The state of the parallel search between its parts (issue 12): the top of the tree, the
// subtrees it deferred, and the result of each subtree searched to the end. A part is
// searched from its box alone (the steps keep no state between boxes), so a run resumed
// from this state, searching only the unfinished subtrees again, ends with the same tree,
// boxes and certificate as a run never stopped. apps/checkpoint.* writes and reads it.
#pragma once

#include <cstdint>
#include <vector>

#include "search/branch_and_prune.h"
#include "generalized_aspects.h"

namespace aspects {

// Output boxes and tree of one part of the search (the top of the tree, or a subtree).
// Only boxes, certified, undecided_kind, signs and diagnostics of `out` are used.
struct SearchPart {
  AspectsResult out;
  std::vector<SearchNode> tree;
  int32_t next_leaf = 0;  // merge cursor: leaves are taken in their local order
};

struct SearchState {
  bool top_done = false;                  // the top was searched to the end
  SearchPart top;
  std::vector<DeferredSubtree> deferred;  // the subtrees the top left, in depth-first order
  std::vector<uint8_t> done;              // per subtree: searched to the end (parts[k] valid)
  std::vector<SearchPart> parts;
};

}  // namespace aspects
