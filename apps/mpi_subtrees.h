// The search of an MPI job spread over its ranks. Rank 0 searches the top of the tree, then
// hands out its deferred subtrees one at a time to whichever thread asks first, its own
// (search_phase) or another rank's (MpiSubtreeServer); the other ranks (search_subtrees_for_rank0)
// search each subtree from its box alone and send back the part and its certificate
// records. Parts travel in messages, not files: the ranks need no shared filesystem.
//
// Messages (little-endian; apps/mpi_job.h sends byte strings of any length):
//   thread s of a rank -> rank 0, Control channel, tag kFromThread + s:
//     u8 0      (one more subtree: sent before the first, then as each is begun, so that
//                the next is there when the thread is free; a thread holds two at most)
//   thread s of a rank -> rank 0, Bulk channel, tag kFromThread + s, sent while the thread
//   searches its next subtree (one part of a thread in flight at a time):
//     u8 1  i32 task  counts  part  u64 R  R bytes   (task searched: part as in
//                                                   apps/search_part_codec.h, its records)
//     u8 2  i32 task  counts  part  u64 R  R bytes   (task stopped: a partial part)
//     counts: i64 nodes, solutions, undecided, discarded, boxes (progress, and the merge's
//     room, before the part is decoded as the merge grafts it)
//   rank 0 -> thread s, tag kToThread + s:
//     i32 task  i32 parent_split  nv × (f64 lo  f64 hi)   (search this)
//     i32 -1                                              (no more: the thread ends)
//   rank 0 -> a rank searching a subtree, tag kStop: empty (rank 0 stopped: stop searching)
//   a rank -> rank 0, tag kRankDone: empty (all its threads have ended, their parts sent)
// Rank 0 answers requests before it takes a part in, so that a thread's next subtree does
// not wait behind the parts of the whole job.
#pragma once

#include "model/model.h"
#include "mpi_job.h"
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
             const std::function<bool()>& stopped, const Returned& returned) override;
  void decode(int32_t task, const std::string& bytes, int factors,
              SearchPart& part) const override;

 private:
  MpiJob& job_;
  int nv_;
  std::vector<int> source_;  // per subtree: the rank that sent its part (for errors)
};

// Another rank's side: `config.threads` threads ask rank 0 for subtrees and search them
// until it has none left. Rank 0's stop message, or SIGINT/SIGTERM to this rank, stops the
// subtrees being searched (config.stop is replaced): they go back partial. With
// `certificate`, each part's records go back too. Throws on a malformed message.
void search_subtrees_for_rank0(MpiJob& job, Model& model, const AspectsConfig& config,
                               bool certificate);

// The depth at which rank 0 cuts the tree into subtrees for P processes of T threads: at
// least 8 (a single process's cut), and deep enough for 256 subtrees a thread: nearly all
// the work sits in a few subtrees near the singular surfaces, and smaller pieces keep the
// last ones handed out short. The result does not depend on it: a subtree is searched from
// its box alone.
int defer_depth_for(int processes, int threads);

}  // namespace aspects
