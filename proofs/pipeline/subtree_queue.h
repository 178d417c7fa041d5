// The deferred subtrees of the search not yet searched, handed out one at a time in
// depth-first order to whoever asks first: this process's threads and, in a distributed
// run, the other processes (remote_subtrees.h). Almost all the work sits near the singular
// surfaces, so a split fixed in advance would leave most searchers idle; taking the next
// subtree when idle balances the load. Who searched a subtree never changes its part.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

namespace aspects {

class SubtreeQueue {
 public:
  // Every subtree k with !done[k].
  explicit SubtreeQueue(const std::vector<uint8_t>& done) {
    for (size_t k = 0; k < done.size(); ++k)
      if (!done[k]) pending_.push_back(int32_t(k));
  }
  SubtreeQueue(const SubtreeQueue&) = delete;
  SubtreeQueue& operator=(const SubtreeQueue&) = delete;

  // The next subtree not yet handed out; -1 when none is left. Thread-safe.
  int32_t claim() {
    const size_t i = next_.fetch_add(1, std::memory_order_relaxed);
    return i < pending_.size() ? pending_[i] : -1;
  }

 private:
  std::vector<int32_t> pending_;
  std::atomic<size_t> next_{0};
};

}  // namespace aspects
