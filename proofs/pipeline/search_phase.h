// Phase 1, the search (paper 4.2, Algorithm 1 with Prove = P1 ∧ P2): the top of the tree,
// then the subtrees below `defer_depth` in parallel, each from its box alone; parts already
// in a resumed state are taken as they are; checkpoints while it runs; the parts merged
// depth first. The result does not depend on the number of threads.
//
// Guarantees: every solution box satisfies P1, P2 and the additional constraints on the
// whole box; S ∪ U covers every feasible solution of f = 0 in the initial domain (coverage).
// A stopped search keeps the cells it did not search as unexplored boxes (in U).
#pragma once

#include <vector>

#include "aspects_config.h"
#include "aspects_search.h"
#include "model/determinant_factors.h"
#include "model/model.h"
#include "parallel.h"
#include "phase_clock.h"
#include "search_state.h"

namespace aspects {

struct SearchOutcome {
  OutputBoxes boxes;  // R = S ∪ U, depth-first order
  std::vector<SearchNode> tree;
  SearchDiagnostics diagnostics;
};

// One deferred subtree searched to the end from its box alone, its certificate records
// into `sink` (may be null): another process's share of a distributed search
// (remote_subtrees.h). Its part is the one search_phase would have made. False when
// config.stop stopped it (the part is then partial, its cells left unexplored).
bool search_subtree(const Model& model, const AspectsConfig& config,
                    const std::vector<Factor>& factors, const DeferredSubtree& subtree,
                    SearchPart& part, TreeSink* sink);

// Laps "search" and "merge" on `clock`.
SearchOutcome search_phase(const Model& model, const AspectsConfig& config,
                           const std::vector<Factor>& factors, Parallel& parallel,
                           PhaseClock& clock);

}  // namespace aspects
