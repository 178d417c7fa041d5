#include "part_merger.h"

#include <stdexcept>

namespace aspects {

void PartMerger::merge(SearchPart& top, std::vector<EncodedPart>* encoded,
                       const Decode& decode) {
  encoded_ = encoded;
  decode_ = decode;
  size_t nodes = top.tree.size(), boxes = top.boxes.size();
  for (size_t k = 0; k < parts_.size(); ++k) {
    const EncodedPart* e = still_encoded(k);
    nodes += e ? size_t(e->nodes) : parts_[k].tree.size();
    boxes += e ? size_t(e->boxes) : size_t(parts_[k].boxes.size());
  }
  tree_.reserve(nodes);
  boxes_.reserve(boxes);
  tree_.emplace_back();
  for (SearchPart& part : parts_) part.next_leaf = 0;
  top.next_leaf = 0;
  graft(top, 0, 0);
  release(top);
}

// Node i of `part` and the tree below it into tree_[id]; the children of an internal node
// take two adjacent new slots, as in the search.
void PartMerger::graft(SearchPart& part, int32_t i, int32_t id) {
  const SearchNode src = part.tree[i];
  if (src.fate == LeafFate::Deferred && !src.internal()) {
    SearchPart& sub = parts_[src.index];
    if (EncodedPart* e = still_encoded(size_t(src.index))) {
      decode_(src.index, e->bytes, sub);
      std::string().swap(e->bytes);
    }
    graft(sub, 0, id);
    release(sub);  // each part is grafted once, whole
    return;
  }
  tree_[id] = src;
  if (src.internal()) {
    const int32_t first = int32_t(tree_.size());
    tree_.emplace_back();
    tree_.emplace_back();
    tree_[id].index = first;
    graft(part, src.left(), first);
    graft(part, src.right(), first + 1);
  } else if (src.index >= 0) {
    if (src.index != part.next_leaf++) throw std::logic_error("merge: leaves out of order");
    tree_[id].index = boxes_.push_copy(part.boxes, src.index);
  }
}

EncodedPart* PartMerger::still_encoded(size_t k) const {
  if (!encoded_ || k >= encoded_->size() || (*encoded_)[k].bytes.empty()) return nullptr;
  return &(*encoded_)[k];
}

// The merged arrays of a part; its diagnostics stay.
void PartMerger::release(SearchPart& part) {
  std::vector<SearchNode>().swap(part.tree);
  part.boxes.release();
}

}  // namespace aspects
