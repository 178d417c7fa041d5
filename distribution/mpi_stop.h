// A rank's stop condition while it searches subtrees for rank 0 (distribution/mpi_subtrees.h): set
// when rank 0 sends the stop message (rank 0 stopped: a limit or a signal), or by SIGINT or
// SIGTERM to this rank. The subtree being searched then comes back partial, as a single
// process keeps the part of a subtree it was searching when it stopped.
#pragma once

#include <atomic>
#include <thread>

#include "distribution/mpi_job.h"
#include "search/stop_condition.h"

namespace aspects {

class RankStop {
 public:
  // Watches, on a thread of its own, for a message from rank 0 with `tag`.
  RankStop(MpiJob& job, int tag);
  ~RankStop();  // stops watching
  RankStop(const RankStop&) = delete;
  RankStop& operator=(const RankStop&) = delete;

  StopCondition& condition() { return stop_; }

 private:
  void watch(MpiJob& job, int tag);

  StopCondition stop_;
  std::atomic<bool> done_{false};
  std::thread watcher_;
};

}  // namespace aspects
