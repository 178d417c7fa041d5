// The search of an MPI job spread over its ranks. Rank 0 searches the top of the tree, then
// hands out its deferred subtrees one at a time to whichever thread asks first, its own
// (search_phase) or another rank's (MpiSubtreeServer); the other ranks (search_subtrees_for_rank0)
// search each subtree from its box alone and send back the part and its certificate
// records, or keep the records (HeldRecords) until rank 0 writes the certificate and asks
// for them: then rank 0 does not spool every record while the search runs. Not with
// checkpoints, which hold the records of the subtrees done. Parts and records travel in
// messages, not files: the ranks need no shared filesystem.
//
// Messages (little-endian; distribution/mpi_job.h sends byte strings of any length):
//   thread s of a rank -> rank 0, Control channel, tag kFromThread + s:
//     u8 0      (one more subtree: sent before the first, then as each is begun, so that
//                the next is there when the thread is free; a thread holds two at most)
//   thread s of a rank -> rank 0, Bulk channel, tag kFromThread + s, sent while the thread
//   searches its next subtree (one part of a thread in flight at a time):
//     u8 1  i32 task  counts  part  u8 0  u64 R  R bytes   (task searched: part as in
//                                             run/search_part_codec.h, its records)
//     u8 1  i32 task  counts  part  u8 1  u64 R            (the same, its R bytes of records
//                                                         held by the sender)
//     u8 2  ...                                   (task stopped: a partial part; likewise)
//     counts: i64 nodes, solutions, undecided, discarded, boxes (progress, and the merge's
//     room, before the part is decoded as the merge grafts it)
//   rank 0 -> thread s, tag kToThread + s:
//     i32 task  u8 H  i32 parent_split  nv × (f64 lo  f64 hi)   (search this; H = 1: keep
//                                                           its records until asked)
//     i32 -1                                              (no more: the thread ends)
//   rank 0 -> a rank searching a subtree, tag kStop: empty (rank 0 stopped: stop searching)
//   a rank -> rank 0, tag kRankDone: empty (all its threads have ended, their parts sent)
//   rank 0 -> a rank done, tag kFetchRecords: u32 k  k × i32 task (as the certificate is
//     written: the records of its next subtrees, up to 16 MB)
//   that rank -> rank 0, Bulk channel, tag kHeldRecords: u32 k  k × (i32 task  u64 R  R bytes)
// Rank 0 answers requests before it takes a part in, so that a thread's next subtree does
// not wait behind the parts of the whole job.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "distribution/mpi_held_records.h"
#include "distribution/mpi_job.h"
#include "model/model.h"
#include "pipeline/aspects_config.h"
#include "pipeline/remote_subtrees.h"

namespace aspects {

// Rank 0's side: serves every other rank until each has said it is done.
class MpiSubtreeServer : public RemoteSubtrees {
 public:
  // `nv`: the model's variables, to read the parts. Once every rank is done, the job's
  // workers wait for rank 0's exit status.
  MpiSubtreeServer(MpiJob& job, int nv) : job_(job), nv_(nv) {}
  void serve(SubtreeQueue& queue, const std::vector<DeferredSubtree>& deferred, int factors,
             const std::function<bool()>& stopped, const Returned& returned,
             bool records_may_wait) override;
  void decode(int32_t task, const std::string& bytes, int factors,
              SearchPart& part) const override;

 private:
  // The records of subtree `task`, held by the rank that searched it (after the search).
  std::string fetch_records(int32_t task);

  MpiJob& job_;
  int nv_;
  // Held records: where each subtree's wait (by task: the order they are spliced), and
  // those received in a batch and not yet spliced.
  struct HeldAt {
    int rank;
    uint64_t size;
  };
  static constexpr uint64_t kFetchBatch = uint64_t(16) << 20;
  std::map<int32_t, HeldAt> held_;
  std::map<int32_t, std::string> fetched_;
  std::vector<int> source_;  // per subtree: the rank that sent its part (for errors)
};

// Another rank's side: `config.threads` threads ask rank 0 for subtrees and search them
// until it has none left. Rank 0's stop message, or SIGINT/SIGTERM to this rank, stops the
// subtrees being searched (config.stop is replaced): they go back partial. With `held` (a
// certificate is written), each part's records go back too, or are kept in `held` when
// rank 0 says so. Throws on a malformed message.
void search_subtrees_for_rank0(MpiJob& job, Model& model, const AspectsConfig& config,
                               HeldRecords* held);

// Then, until rank 0's exit status (returned): sends rank 0 the held records it asks for.
int serve_held_records_until_exit(MpiJob& job, const HeldRecords* held);

// The depth at which rank 0 cuts the tree into subtrees for P processes of T threads: at
// least 8 (a single process's cut), and deep enough for 256 subtrees a thread: nearly all
// the work sits in a few subtrees near the singular surfaces, and smaller pieces keep the
// last ones handed out short. The result does not depend on it: a subtree is searched from
// its box alone.
int defer_depth_for(int processes, int threads);

}  // namespace aspects
