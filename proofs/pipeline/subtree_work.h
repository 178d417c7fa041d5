// What the search of each deferred subtree cost, for a scaling study of the distributed
// search (`aspects solve --subtree-stats`, bench/scaling_replay.py). Observed only: the
// search never reads it, so the result does not change.
#pragma once

#include <time.h>

#include <chrono>
#include <cstdint>
#include <functional>

#include "search_state.h"

namespace aspects {

// The seconds one part of the search took. CPU seconds are the searching thread's own
// (a subtree is searched by one thread from start to end), so other processes sharing the
// cores do not inflate them as they inflate the wall seconds.
struct PartWork {
  double cpu_seconds = 0;
  double wall_seconds = 0;
};

// Started when made; work() reads both clocks of the calling thread.
class PartClock {
 public:
  PartClock() : cpu_(thread_cpu()), wall_(std::chrono::steady_clock::now()) {}
  PartWork work() const {
    return {thread_cpu() - cpu_,
            std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_).count()};
  }

 private:
  static double thread_cpu() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
  }
  double cpu_;
  std::chrono::steady_clock::time_point wall_;
};

// The observers (AspectsConfig::subtree_observer); each may be empty.
struct ReturnedPart;  // remote_subtrees.h

struct SubtreeObserver {
  // Once, when the top of the tree is searched: the state with its deferred subtrees.
  std::function<void(const SearchState& st, const PartWork& top)> top_searched;
  // Each subtree searched here, from the thread that searched it (concurrently).
  std::function<void(int32_t task, const SearchPart& part, const PartWork& work)> searched_here;
  // Each part another process sent back (an MPI job; decoded or not), with the bytes of
  // its certificate records; its cost is not known here. From the thread serving the other
  // processes.
  std::function<void(int32_t task, const ReturnedPart& part, size_t record_bytes)> returned;
};

}  // namespace aspects
