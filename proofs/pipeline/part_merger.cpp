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

// The tree below node i of `part` into tree_[id], depth first, left before right; the
// children of an internal node take two adjacent new slots, as in the search. An explicit
// stack, not recursion: a search stopped deep down (eps far below the domain's width)
// leaves trees tens of thousands of levels deep, more than a thread's stack holds.
void PartMerger::graft(SearchPart& root, int32_t i, int32_t id) {
  struct Item {
    SearchPart* part;
    int32_t i;   // the node to graft; kRelease: free `part`, grafted whole
    int32_t id;  // its slot in tree_
  };
  constexpr int32_t kRelease = -1;
  std::vector<Item> stack{{&root, i, id}};
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    SearchPart& part = *it.part;
    if (it.i == kRelease) {
      release(part);  // each part is grafted once, whole
      continue;
    }
    if (size_t(it.i) >= part.tree.size()) throw std::logic_error("merge: a node outside its part");
    const SearchNode src = part.tree[size_t(it.i)];
    if (src.fate == LeafFate::Deferred && !src.internal()) {
      SearchPart& sub = parts_[size_t(src.index)];
      if (EncodedPart* e = still_encoded(size_t(src.index))) {
        decode_(src.index, e->bytes, sub);
        std::string().swap(e->bytes);
      }
      stack.push_back({&sub, kRelease, 0});
      stack.push_back({&sub, 0, it.id});
      continue;
    }
    tree_[size_t(it.id)] = src;
    if (src.internal()) {
      const int32_t first = int32_t(tree_.size());
      tree_.emplace_back();
      tree_.emplace_back();
      tree_[size_t(it.id)].index = first;
      stack.push_back({&part, src.right(), first + 1});  // the left child comes out first
      stack.push_back({&part, src.left(), first});
    } else if (src.index >= 0) {
      if (src.index != part.next_leaf++) throw std::logic_error("merge: leaves out of order");
      tree_[size_t(it.id)].index = boxes_.push_copy(part.boxes, src.index);
    }
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
