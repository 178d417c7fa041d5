// A search tree far deeper than any thread's stack allows a recursion over it: a run stopped
// tens of thousands of levels down must still merge and write its result. The tests that
// walk it (graft, the part codec, the neighbourhood graph) must get through it iteratively.
// 200,000 levels: a recursion of even 48-byte frames passes 8 MiB.
#pragma once

#include <cstdint>
#include <vector>

#include "search/branch_and_prune.h"
#include "search/output_boxes.h"

namespace aspects {

constexpr int kDeepTreeLevels = 200000;

struct DeepTree {
  std::vector<SearchNode> tree;
  OutputBoxes boxes;
};

// `levels` bisections of x, each left child bisected again, numbered as the search numbers
// its nodes (the k-th internal node's children are nodes 2k + 1 and 2k + 2). At the bottom,
// the left leaf is `bottom` (index 0: output box 0, or deferred subtree 0) and its right
// sibling an undecided box. The right child of level k < `boxed_levels` is an undecided box
// too; every other right child a discarded leaf. Boxes are numbered depth first, as the
// search numbers them; box b spans [b, b + 1] in x and [0, 1] in the other variables, so
// consecutive boxes touch and no others. Each has p signs, all +1.
inline DeepTree deep_tree(int levels, LeafFate bottom, int nv, int p, int boxed_levels = 0) {
  DeepTree d{{}, OutputBoxes(nv, p)};
  d.tree.reserve(2 * size_t(levels) + 1);
  d.tree.emplace_back();
  std::vector<int32_t> boxed;  // the right children holding a box, from the top
  int32_t node = 0;
  for (int k = 0; k < levels; ++k) {
    const int32_t left = int32_t(d.tree.size());
    d.tree[size_t(node)].set_children(0, 1.0 - double(k + 1) * 0x1p-40, left);
    d.tree.emplace_back();
    d.tree.emplace_back();
    d.tree[size_t(left) + 1].reason = 0;  // discarded by equation 0
    if (k < boxed_levels) boxed.push_back(left + 1);
    node = left;
  }
  const std::vector<int8_t> signs(size_t(p), 1);
  auto add_box = [&](UndecidedKind kind) {
    const int32_t b = d.boxes.size();
    Box box(size_t(nv), Interval(0.0, 1.0));
    box[0] = Interval(double(b), double(b) + 1);
    return d.boxes.push(box, false, kind, signs.data());
  };
  auto undecided = [&](int32_t leaf) {
    SearchNode& s = d.tree[size_t(leaf)];
    s.fate = LeafFate::Undecided;
    s.reason = -1;
    s.index = add_box(UndecidedKind::NoExistence);
  };
  d.tree[size_t(node)].fate = bottom;
  d.tree[size_t(node)].index = bottom == LeafFate::Deferred ? 0
                               : add_box(bottom == LeafFate::Unexplored ? UndecidedKind::Unexplored
                                                                        : UndecidedKind::NoExistence);
  if (levels > 0 && int(boxed.size()) < levels) undecided(node + 1);
  for (size_t k = boxed.size(); k-- > 0;) undecided(boxed[k]);  // depth first: the deepest first
  return d;
}

}  // namespace aspects
