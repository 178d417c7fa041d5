// The threads of one run: a oneTBB arena of the configured size, in which every phase runs
// its parallel loops. The results never depend on the number of threads: each phase cuts
// its work into pieces fixed in advance and joins their results in order. oneTBB lends its
// workers to every arena of the process, and MPFR's precision is per thread: each task
// takes the run's precision before it makes an interval, whatever another run left there.
#pragma once

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <functional>

#include "aspects/for_each_index.h"
#include "numerics/interval.h"

namespace aspects {

class Parallel {
 public:
  Parallel(int threads, long precision)
      : arena_(std::max(1, threads)),
        precision_(precision),
        for_each_([this](int n, const std::function<void(int32_t)>& body) {
          // One index per task: the callers' indices are blocks of boxes or CSNCs (a few
          // large CSNCs hold nearly all the witness work).
          arena_.execute([&] {
            tbb::parallel_for(
                tbb::blocked_range<int>(0, n, 1),
                [&](const tbb::blocked_range<int>& r) {
                  set_working_precision(precision_);
                  for (int i = r.begin(); i < r.end(); ++i) body(i);
                },
                tbb::simple_partitioner());
          });
        }) {}
  Parallel(const Parallel&) = delete;
  Parallel& operator=(const Parallel&) = delete;

  tbb::task_arena& arena() { return arena_; }
  long precision() const { return precision_; }
  const ForEachIndex& for_each() const { return for_each_; }

 private:
  tbb::task_arena arena_;
  long precision_;
  ForEachIndex for_each_;
};

}  // namespace aspects
