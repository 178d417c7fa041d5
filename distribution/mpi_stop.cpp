#include "distribution/mpi_stop.h"

#include <chrono>

namespace aspects {

RankStop::RankStop(MpiJob& job, int tag) {
  stop_.set_watch_signals(true);
  watch_stop_signals();
  watcher_ = std::thread([this, &job, tag] { watch(job, tag); });
}

RankStop::~RankStop() {
  done_ = true;
  watcher_.join();
}

// Probing every few milliseconds costs nothing next to a search, and a stop is seen at once.
void RankStop::watch(MpiJob& job, int tag) {
  while (!done_) {
    if (job.probe(0, tag)) {
      job.receive(0, tag);
      stop_.request(StopReason::Signal);  // the reason is rank 0's; this rank only stops
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

}  // namespace aspects
