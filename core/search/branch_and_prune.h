// Algorithm 1 (paper 3.1 and 4.2): generic branch and prune over injected steps.
//   Extract: depth first (a stack); Prune, Prove, Branch: supplied by the caller.
// The search records its bisection tree: every node's split variable and exact split
// point, and the fate of every leaf, so coverage can be re-derived (the cells of the
// leaves partition the initial box; pruning only removes points that are not solutions).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "model/constraints.h"
#include "search/bisector.h"
#include "numerics/interval.h"
#include "search/stop_condition.h"
#include "search/verdict.h"

namespace aspects {

// Unexplored: the search stopped before this cell (StopCondition); its output box is the
// cell, which may hold solutions, like an undecided box.
enum class LeafFate : uint8_t { Solution, Undecided, Discarded, Deferred, Unexplored };

// 16 bytes: 22 M nodes on 3-RPR at eps 0.3, 232 M at eps 0.1. The two
// children of an internal node are adjacent (right = left + 1), so one index serves both
// kinds of node.
struct SearchNode {
  double split = 0;      // internal: exact split point: left has v <= split, right v >= split
  int32_t index = -1;    // internal: the left child; leaf: the output box in R, or -1
                         // (discarded); deferred leaf: its subtree task
  int16_t reason = -1;   // discarded leaf: what refuted it (see Steps::prune)
  int8_t split_var = -1; // internal: the bisected variable; -1 for a leaf
  LeafFate fate = LeafFate::Discarded;

  bool internal() const { return split_var >= 0; }
  int32_t left() const { return index; }
  int32_t right() const { return index + 1; }
  int32_t leaf() const { return internal() ? -1 : index; }  // -1: none
  void set_children(int var, double at, int32_t first) {
    split_var = int8_t(var);
    split = at;
    index = first;
  }
};
static_assert(sizeof(SearchNode) == 16, "a tree node stays 16 bytes");
// split_var fits: a model has at most 16 variables (the parser says so). A larger prune
// reason (over 32,000 constraints) stops the search with an error.
constexpr int32_t kMaxPruneReason = 32767;

// What Prune decided about a box: refuted (it holds no solution; the reason is recorded in
// the tree), or kept, contracted, with the truth of the additional constraints on it.
struct PruneResult {
  int32_t refuted_by = -1;          // >= 0: refuted, and why
  Truth constraints = Truth::True;  // kept: the constraints on the contracted box
  bool refuted() const { return refuted_by >= 0; }
};

// What Prove decided about a box; on Verdict::Solution the step has stored it (and its
// proof) as output box `index`.
struct ProveResult {
  Verdict verdict;
  int32_t index = -1;
};

// The steps of Algorithm 1 for one problem. They keep no result from one call to the
// next: what a later step needs of an earlier one is handed to it.
class BranchAndPruneSteps {
 public:
  virtual ~BranchAndPruneSteps() = default;
  // Prune_c: contracts the box, removing no solution.
  virtual PruneResult prune(Box& box) = 0;
  // Prove_c: the verdict on the box, as Prune returned it.
  virtual ProveResult prove(const Box& box) = 0;
  // Stores an undecided box (a leaf that Prove rejected for `why`, with what Prune said of
  // it); its output index.
  virtual int32_t keep_undecided(const Box& box, Verdict why, const PruneResult& pruned) = 0;
  // Stores a cell the search stopped before (neither pruned nor proved); its output index.
  virtual int32_t keep_unexplored(const Box& box) = 0;
  // Branch: the variable and the point to bisect at, or var = -1 for a leaf.
  virtual SplitChoice choose_split(const Box& box, const SplitContext& ctx) = 0;
  // Told where a box was bisected, and where a subtree was deferred (for the
  // certificate).
  virtual void branched(int /*var*/, double /*at*/) {}
  virtual void deferred(int32_t /*task*/) {}
};

struct SearchStats {
  std::atomic<long> processed{0}, solutions{0}, undecided{0}, discarded{0};
  // Progress only (never a claim): the share of the initial domain's volume whose cells are
  // decided (solution, undecided or discarded leaves), when `domain` is set before the
  // search. A variable of zero width (3-RRR*: x3 ∈ [0, 0]) counts as a factor 1.
  std::vector<double> domain_width;
  std::atomic<double> decided{0};  // by this run
  double resumed_share = 0;        // decided before (a resumed run), not in `decided`
  double share(const Box& cell) const;
  void add_decided(double share);
};

// A subtree left for later (parallel) processing: its box, as Extract would have
// returned it, and the split that produced it.
struct DeferredSubtree {
  Box box;
  int parent_split;
  int32_t node;  // its node in the tree that deferred it
};

// Runs Algorithm 1 from `root`. The tree's node 0 is the root. With `defer_depth` >= 0,
// nodes at that depth are not processed but appended to *deferred (in depth-first order)
// and marked LeafFate::Deferred; each can then be searched on its own, with the same
// result as if the search had continued: the steps keep no state between boxes.
// With `stop`, the search asks it before each box; once it says stop, that box and every
// one still on the stack become Unexplored leaves (output boxes, in depth-first order).
// Returns false when some leaf was left unexplored.
bool branch_and_prune(const Box& root, BranchAndPruneSteps& steps, std::vector<SearchNode>& tree,
                      SearchStats& stats, const std::function<void()>& on_progress = {},
                      int root_parent_split = -1, int defer_depth = -1,
                      std::vector<DeferredSubtree>* deferred = nullptr,
                      StopCondition* stop = nullptr);

}  // namespace aspects
