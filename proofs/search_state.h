// The state of the parallel search between its parts: the top of the tree, the
// subtrees it deferred, and the result of each subtree searched to the end. A part is
// searched from its box alone (the steps keep no state between boxes), so a run resumed
// from this state, searching only the unfinished subtrees again, ends with the same tree,
// boxes and certificate as a run never stopped. run/checkpoint.* writes and reads it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pipeline/aspects_search.h"
#include "search/branch_and_prune.h"
#include "search/output_boxes.h"

namespace aspects {

// Output boxes and tree of one part of the search (the top of the tree, or a subtree).
struct SearchPart {
  OutputBoxes boxes;
  SearchDiagnostics diagnostics;
  std::vector<SearchNode> tree;
  int32_t next_leaf = 0;  // merge cursor: leaves are taken in their local order
};

// A part in the bytes another process sent it in, with its sizes (the merge reserves room
// for everything before it decodes anything).
struct EncodedPart {
  std::string bytes;
  long nodes = 0, boxes = 0;
};

struct SearchState {
  bool top_done = false;                  // the top was searched to the end
  SearchPart top;
  std::vector<DeferredSubtree> deferred;  // the subtrees the top left, in depth-first order
  std::vector<uint8_t> done;              // per subtree: searched to the end (parts[k] valid)
  std::vector<SearchPart> parts;
  // Per subtree: a part another process sent back, still in the bytes it came in (see
  // pipeline/remote_subtrees.h; empty: parts[k] holds it), until the merge grafts it.
  std::vector<EncodedPart> encoded;
};

}  // namespace aspects
