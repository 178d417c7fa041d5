// The search's parts (the top of the tree and its deferred subtrees) joined into one tree
// and one store of output boxes, numbered depth first: the order of the certificate's
// records, whatever the number of threads that searched them.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "search_state.h"

namespace aspects {

class PartMerger {
 public:
  PartMerger(std::vector<SearchPart>& parts, OutputBoxes& boxes, std::vector<SearchNode>& tree)
      : parts_(parts), boxes_(boxes), tree_(tree) {}

  // Decodes encoded part k's bytes into the part (pipeline/remote_subtrees.h).
  using Decode = std::function<void(int32_t k, const std::string& bytes, SearchPart& part)>;

  // Grafts every part below `top`'s deferred leaves. Room for everything is reserved first,
  // and each part's arrays are freed once grafted, so the search is never held twice. A part
  // with bytes in `encoded` (may be null) is decoded just before it is grafted, its bytes
  // then freed.
  void merge(SearchPart& top, std::vector<EncodedPart>* encoded = nullptr,
             const Decode& decode = {});

 private:
  void graft(SearchPart& part, int32_t i, int32_t id);
  static void release(SearchPart& part);
  EncodedPart* still_encoded(size_t k) const;  // part k's bytes, if not decoded yet

  std::vector<SearchPart>& parts_;
  std::vector<EncodedPart>* encoded_ = nullptr;
  Decode decode_;
  OutputBoxes& boxes_;
  std::vector<SearchNode>& tree_;
};

}  // namespace aspects
