#include "search/branch_and_prune.h"

#include <stdexcept>
#include <utility>

namespace aspects {

double SearchStats::share(const Box& cell) const {
  double f = 1;
  for (size_t v = 0; v < domain_width.size(); ++v)
    if (domain_width[v] > 0) f *= (cell[v].hi_up() - cell[v].lo_down()) / domain_width[v];
  return f;
}

void SearchStats::add_decided(double x) {
  double old = decided.load(std::memory_order_relaxed);
  while (!decided.compare_exchange_weak(old, old + x, std::memory_order_relaxed)) {
  }
}

bool branch_and_prune(const Box& root, BranchAndPruneSteps& steps, std::vector<SearchNode>& tree,
                      SearchStats& stats, const std::function<void()>& on_progress,
                      int root_parent_split, int defer_depth,
                      std::vector<DeferredSubtree>* deferred, StopCondition* stop) {
  struct Item {
    Box box;
    int32_t node;
    int parent_split;
    int depth;
  };
  tree.clear();
  tree.emplace_back();
  std::vector<Item> stack;  // Extract: depth first
  stack.push_back({root, 0, root_parent_split, 0});
  bool complete = true;
  while (!stack.empty()) {
    Item it = std::move(stack.back());
    stack.pop_back();
    SearchNode& node = tree[it.node];
    if (it.depth == defer_depth) {
      node.fate = LeafFate::Deferred;
      node.index = int32_t(deferred->size());
      steps.deferred(node.index);
      deferred->push_back({std::move(it.box), it.parent_split, it.node});
      continue;
    }
    if (stop && !stop->admit(stats.solutions + stats.undecided)) {
      node.fate = LeafFate::Unexplored;
      node.index = steps.keep_unexplored(it.box);
      complete = false;
      continue;
    }
    ++stats.processed;
    if (on_progress && (stats.processed & 1023) == 0) on_progress();
    // The cell's share, before Prune narrows it: the refuted slabs are decided too.
    const double cell_share = stats.domain_width.empty() ? 0 : stats.share(it.box);
    const PruneResult pruned = steps.prune(it.box);
    if (pruned.refuted()) {
      stats.add_decided(cell_share);
      node.fate = LeafFate::Discarded;
      if (pruned.refuted_by > kMaxPruneReason) throw std::length_error("prune reason out of range");
      node.reason = int16_t(pruned.refuted_by);
      ++stats.discarded;
      continue;
    }
    const ProveResult proved = steps.prove(it.box);
    const Verdict verdict = proved.verdict;
    if (verdict == Verdict::Solution) {
      node.fate = LeafFate::Solution;
      node.index = proved.index;
      ++stats.solutions;
      stats.add_decided(cell_share);
      continue;
    }
    SplitChoice split = steps.choose_split(it.box, {it.parent_split, verdict});
    if (split.var < 0) {
      node.fate = LeafFate::Undecided;
      node.index = steps.keep_undecided(it.box, verdict, pruned);
      ++stats.undecided;
      stats.add_decided(cell_share);
      continue;
    }
    if (cell_share > 0) stats.add_decided(cell_share - stats.share(it.box));  // the slabs
    int var = split.var;
    double p = split.at;
    steps.branched(var, p);
    int32_t left = int32_t(tree.size()), right = left + 1;
    node.set_children(var, p, left);  // `node` may dangle after emplace_back: not used below
    tree.emplace_back();
    tree.emplace_back();
    Box hi = it.box;
    hi[var].set_hull(p, it.box[var].hi_up());
    it.box[var].set_hull(it.box[var].lo_down(), p);
    // Push right first so the left half is extracted next (depth first, left to right).
    stack.push_back({std::move(hi), right, var, it.depth + 1});
    stack.push_back({std::move(it.box), left, var, it.depth + 1});
  }
  return complete;
}

}  // namespace aspects
