// One MPI job (Open MPI, through MPI's C API): initialised when made, finalised when
// destroyed. Messages are byte strings of any length. Waiting for a message or for a send
// to complete polls and sleeps (20 µs growing to 1 ms) instead of blocking: Open MPI's
// blocking calls spin, and on a rank that also searches a spinning thread takes a core
// from the search. MPI is called by one thread at a time (MPI_THREAD_SERIALIZED): threads
// that share the job go through its lock. Two channels (communicators) keep a rank's small
// requests apart from the large parts it sends back: rank 0 answers requests first.
#pragma once

#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace aspects {

// Where the other ranks are, for what rank 0 must do when its run ends
// (MpiJob::finish).
enum class WorkerState {
  Idle,       // not started, or already gone (a refused run): nothing to tell them
  Searching,  // waiting for subtrees from rank 0
  Waiting,    // done with the search, waiting for rank 0's exit status
};

class MpiJob {
 public:
  static constexpr int kAny = -1;  // any source, or any tag
  // Control: requests, tasks, stops, exit statuses. Bulk: the parts searched (MB each).
  enum Channel { Control, Bulk };

  MpiJob();   // MPI_Init_thread (throws if MPI cannot be called from several threads)
  ~MpiJob();  // MPI_Finalize
  MpiJob(const MpiJob&) = delete;
  MpiJob& operator=(const MpiJob&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // The ranks on this rank's node (shared memory), this one included.
  int ranks_on_this_node() const;

  // Returns once `bytes` are sent (the buffer reusable).
  void send(int to, int tag, const std::string& bytes, Channel c = Control);
  // The next message from `from` with `tag` (kAny: any); its sender and tag when asked.
  std::string receive(int from, int tag, int* sender = nullptr, int* found_tag = nullptr,
                      Channel c = Control);
  // Whether a message from `from` with `tag` (kAny: any) waits to be received; does not wait.
  bool probe(int from, int tag, Channel c = Control);

  // Every rank's `mine` (all of one size) on rank 0, in rank order; empty elsewhere.
  std::vector<std::string> gather(const std::string& mine);
  // Rank 0's `values` on every rank.
  std::vector<int> broadcast(std::vector<int> values);

  // Rank 0, at the end of its run: tells waiting ranks the exit status, or ends the job
  // (MPI_Abort) when they are still searching: the run failed before handing out all the
  // work, and they would wait for ever.
  void finish(int exit_code);
  void set_workers(WorkerState s) { workers_ = s; }
  // Other ranks: rank 0's exit status, once its run has ended. Rank 0's other messages
  // until then go to `other` (its requests for held records: distribution/mpi_subtrees.h), or are
  // dropped (a stop sent before rank 0 knew this rank was done).
  int wait_for_exit_status(const std::function<void(int tag, const std::string& message)>& other = {});

  [[noreturn]] void abort(int exit_code);

 private:
  int rank_ = 0, size_ = 1;
  void* bulk_ = nullptr;  // the Bulk channel's communicator (MPI_Comm, kept out of this header)
  WorkerState workers_ = WorkerState::Idle;
  std::mutex lock_;
};

}  // namespace aspects
