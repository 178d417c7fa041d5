// A run of the compiled module on a worker thread while the caller's thread, holding the
// GIL between waits, runs Python's signal handlers and a progress callback: what
// aspects.solve and aspects.count share.
#pragma once

#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "py_common.h"
#include "search/stop_condition.h"

namespace aspects::py {

// What the worker reports, read by the polling thread.
struct Progress {
  std::mutex mu;
  long processed = 0, solutions = 0, undecided = 0;
  double decided = 0;
  std::vector<std::pair<std::string, double>> phases;
  // Set under `mu` by the run, read without it by the polling thread.
  std::atomic<bool> changed{false};
};

// What stderr says at a first Ctrl-C (StopScope::Search) and at a second one.
struct InterruptNotes {
  const char* first;
  const char* second;
};

// Runs `work` on a worker thread while this thread, holding the GIL between waits, runs
// signal handlers and the progress callback. A KeyboardInterrupt interrupts `stop` (the
// first the search, the second the whole run); an exception of another handler or of the
// callback stops the whole run, and is raised once the run ended.
void run_polling(const std::function<void()>& work, StopCondition& stop, Progress& progress,
                 const pyb::object& callback, const InterruptNotes& notes, bool& interrupted);

}  // namespace aspects::py
