// Deferred subtrees searched by other processes (an MPI job: apps/mpi_subtrees.*) beside
// this process's threads. Both take subtrees from one SubtreeQueue. A part comes back
// whole, as this process would have searched it (a subtree is searched from its box
// alone), so the merged tree, boxes and certificate do not depend on who searched what.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "search/branch_and_prune.h"
#include "search_state.h"
#include "subtree_queue.h"

namespace aspects {

// How far another process searched a subtree it sends back.
enum class PartOutcome {
  Complete,  // to the end
  Stopped,   // until a stop (a limit or a signal): the cells left are unexplored boxes
};

class RemoteSubtrees {
 public:
  virtual ~RemoteSubtrees() = default;

  // A subtree searched elsewhere: its part and its certificate records (TreeSink records
  // as certificates/certificate_writer.h writes them; empty without a certificate).
  using Returned = std::function<void(int32_t task, PartOutcome outcome, SearchPart&& part,
                                      std::string&& records)>;

  // Runs on a thread of its own while this process searches: hands out subtrees claimed
  // from `queue` (none once `stopped` says so: this process then marks them unexplored,
  // and the other processes stop the subtrees they are searching), calls `returned` for
  // each part that comes back (its boxes have `factors` signs each), and returns when every
  // other process has finished. A Stopped part comes back when another process was stopped
  // (by this one, or by a signal of its own). Throws when another process sends something
  // that is not such a part.
  virtual void serve(SubtreeQueue& queue, const std::vector<DeferredSubtree>& deferred,
                     int factors, const std::function<bool()>& stopped,
                     const Returned& returned) = 0;
};

}  // namespace aspects
