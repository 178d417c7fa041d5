// The search's parts (the top of the tree and its deferred subtrees) joined into one tree
// and one store of output boxes, numbered depth first: the order of the certificate's
// records, whatever the number of threads that searched them.
#pragma once

#include <vector>

#include "search_state.h"

namespace aspects {

class PartMerger {
 public:
  PartMerger(std::vector<SearchPart>& parts, OutputBoxes& boxes, std::vector<SearchNode>& tree)
      : parts_(parts), boxes_(boxes), tree_(tree) {}

  // Grafts every part below `top`'s deferred leaves. Room for everything is reserved first,
  // and each part's arrays are freed once grafted, so the search is never held twice.
  void merge(SearchPart& top);

 private:
  void graft(SearchPart& part, int32_t i, int32_t id);
  static void release(SearchPart& part);

  std::vector<SearchPart>& parts_;
  OutputBoxes& boxes_;
  std::vector<SearchNode>& tree_;
};

}  // namespace aspects
