// What a run of the method of paper Section 4 is asked to do (proofs/generalized_aspects.h),
// read by every phase.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "certificate_sink.h"
#include "numerics/arithmetic.h"
#include "search/bisector.h"
#include "search/branch_and_prune.h"
#include "search/stop_condition.h"
#include "subtree_work.h"

namespace aspects {

struct SearchState;
class RemoteSubtrees;

struct AspectsConfig {
  double eps = 0.1;
  double tau = 1.01;
  int max_newton_iterations = 8;
  bool keep_link_proofs = true;       // P3 data, for the certificate
  // Prove every link between neighbouring solution boxes, or only those that join two
  // components not yet joined (a spanning forest: the same CSNCs, far fewer proofs).
  bool all_links = false;
  int threads = 1;
  // Every evaluator of the run is made with it (its precision is the calling thread's,
  // which each of the run's threads takes: pipeline/parallel.h).
  Arithmetic arithmetic = Arithmetic::DoublesFirst;
  // Told how each evaluator the phases make computes (ModelEvaluator::arithmetic), from
  // the thread that made it: a test sees each run compute as it asked.
  std::function<void(Arithmetic)> evaluator_made;
  // Threads of the phases after the search, if more (0: `threads`): in an MPI job, rank 0
  // takes over the cores of the ranks on its node, idle once the search is over.
  int later_threads = 0;
  BisectorKind bisector = BisectorKind::RoundRobin;
  double split_fraction = 0.5;  // where a box is cut (search/bisector.h)
  int defer_depth = 8;  // subtrees below this depth are searched in parallel
  // Other processes that search subtrees too (an MPI job); null: this process alone.
  // Not with a box budget: it counts this process's boxes only.
  RemoteSubtrees* remote = nullptr;
  CertificateSink* certificate = nullptr;  // receives the tree records while solving
  // Put recorded ends on the grids of certificate format 3 (proofs/certificate_grid.h):
  // contractions, Q~, IMAGE and link witnesses, each moved outward or within what was
  // proved, so the boxes differ from a run without it in the last few of 2^16 steps.
  bool grid_records = false;
  // Limits and signals (search/stop_condition.h), asked by every phase. A stopped search
  // keeps the cells not yet searched as unexplored output boxes; a later phase that stops
  // keeps what it established (each phase says what), so every claim of the result holds.
  StopCondition* stop = nullptr;
  // Resuming (proofs/search_state.h): the parts already searched are taken from here,
  // the others searched; the state is consumed (empty on return).
  SearchState* resume = nullptr;
  // Called every `checkpoint_seconds` while subtrees are searched, and once more when the
  // search stopped early, with the state and which subtrees are done (a snapshot: parts
  // not done may be changing). From a worker thread, never two calls at once.
  std::function<void(const SearchState&, const std::vector<uint8_t>& done)> checkpoint;
  double checkpoint_seconds = 0;
  std::function<void(const SearchStats&)> progress;
  // Told what each part of the search cost (--subtree-stats); never changes the result.
  SubtreeObserver subtree_observer;
  // Told of each phase as it ends (its name as in summary.json's `phases`, its seconds),
  // on the calling thread.
  std::function<void(const std::string& phase, double seconds)> phase_done;

  // The phases after the search ask this one: the whole run stops (search/stop_condition.h).
  bool stopped() const { return stop && stop->poll(); }
  // The search asks this one between units that are not boxes: a first interrupt or a
  // spent box budget stops the search alone.
  bool search_stopped() const { return stop && stop->search_stopped(); }
  // Reports an evaluator's arithmetic to evaluator_made, if set.
  void made(Arithmetic a) const {
    if (evaluator_made) evaluator_made(a);
  }
};

}  // namespace aspects
