// Deferred subtrees searched by other processes (an MPI job: distribution/mpi_subtrees.*) beside
// this process's threads. Both take subtrees from one SubtreeQueue. A part comes back
// whole, as this process would have searched it (a subtree is searched from its box
// alone), so the merged tree, boxes and certificate do not depend on who searched what.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
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

// A part searched by another process, as it came back: decoded, or (an MPI job) still the
// bytes it travelled in, which RemoteSubtrees::decode reads as the merge grafts it. Taking
// a part in is then a copy, which matters because one thread takes in the parts of the
// whole job.
struct ReturnedPart {
  SearchPart part;    // decoded, when `bytes` is empty
  std::string bytes;  // or encoded
  // Its nodes, the leaves of each fate (progress) and its output boxes (the merge's room),
  // before it is decoded.
  long nodes = 0, solutions = 0, undecided = 0, discarded = 0, boxes = 0;
  // Its certificate records' size, and, when the process that searched it keeps them until
  // the certificate is written (serve()'s `records_may_wait`), what returns them then (once,
  // after serve() has returned).
  uint64_t record_bytes = 0;
  std::function<std::string()> fetch_records;
};

// Counts `part`'s nodes and the leaves of each fate into `into`.
inline void count_leaves(const SearchPart& part, ReturnedPart& into) {
  into.nodes = long(part.tree.size());
  into.boxes = long(part.boxes.size());
  into.solutions = into.undecided = into.discarded = 0;
  for (const SearchNode& node : part.tree) {
    if (node.internal()) continue;
    into.solutions += node.fate == LeafFate::Solution;
    into.undecided += node.fate == LeafFate::Undecided;
    into.discarded += node.fate == LeafFate::Discarded;
  }
}

class RemoteSubtrees {
 public:
  virtual ~RemoteSubtrees() = default;

  // A subtree searched elsewhere: its part and its certificate records (TreeSink records
  // as certificates/certificate_writer.h writes them; empty without a certificate, or when
  // they wait with the process that searched it: ReturnedPart::fetch_records).
  using Returned = std::function<void(int32_t task, PartOutcome outcome, ReturnedPart&& part,
                                      std::string&& records)>;

  // The part of subtree `task` from the bytes it came back in (ReturnedPart::bytes), with
  // `factors` signs a box. Called after serve() has returned, as the merge grafts it.
  // Throws when the bytes are not such a part.
  virtual void decode(int32_t task, const std::string& bytes, int factors,
                      SearchPart& part) const {
    (void)task, (void)bytes, (void)factors, (void)part;
    throw std::logic_error("RemoteSubtrees: this server returns decoded parts");
  }

  // Runs on a thread of its own while this process searches: hands out subtrees claimed
  // from `queue` (none once `stopped` says so: this process then marks them unexplored,
  // and the other processes stop the subtrees they are searching), calls `returned` for
  // each part that comes back (its boxes have `factors` signs each), and returns when every
  // other process has finished. A Stopped part comes back when another process was stopped
  // (by this one, or by a signal of its own). With `records_may_wait`, a part's records
  // may stay where it was searched until the certificate is written: rank 0 of an MPI job
  // then does not take in and spool every record while the search runs (48 GB of text on
  // 3-RPR at eps 0.1), which is what bounded the job's speed-up. Not when a checkpoint must
  // hold them. Throws when another process sends something that is not such a part.
  virtual void serve(SubtreeQueue& queue, const std::vector<DeferredSubtree>& deferred,
                     int factors, const std::function<bool()>& stopped,
                     const Returned& returned, bool records_may_wait) = 0;
};

}  // namespace aspects
