#include "py_polling.h"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <thread>

namespace aspects::py {

namespace {

pyb::dict progress_dict(Progress& p, double seconds) {
  std::lock_guard<std::mutex> lock(p.mu);
  pyb::dict d;
  d["processed"] = p.processed;
  d["solutions"] = p.solutions;
  d["undecided"] = p.undecided;
  d["decided"] = p.decided;
  d["seconds"] = seconds;
  pyb::list phases;
  for (auto& [name, s] : p.phases) phases.append(pyb::make_tuple(name, s));
  d["phases"] = phases;
  p.changed = false;
  return d;
}

}  // namespace

void run_polling(const std::function<void()>& work, StopCondition& stop, Progress& progress,
                 const pyb::object& callback, const InterruptNotes& notes, bool& interrupted) {
  std::mutex mu;
  std::condition_variable cv;
  bool done = false;
  std::exception_ptr failure;
  std::unique_ptr<pyb::error_already_set> callback_error;
  const auto start = std::chrono::steady_clock::now();
  // Ctrl-C, seen by the signal check or raised inside the callback (tqdm's, say): the
  // interrupt a SIGINT is on the command line, never the callback's failure.
  auto on_interrupt = [&] {
    interrupted = true;
    const StopScope scope = stop.interrupt();
    PySys_WriteStderr("%s", scope == StopScope::Search ? notes.first : notes.second);
  };
  {
    pyb::gil_scoped_release release;
    std::thread worker([&] {
      try {
        work();
      } catch (...) {
        failure = std::current_exception();
      }
      std::lock_guard<std::mutex> lock(mu);
      done = true;
      cv.notify_all();
    });
    for (;;) {
      {
        std::unique_lock<std::mutex> lock(mu);
        if (cv.wait_for(lock, std::chrono::milliseconds(100), [&] { return done; })) break;
      }
      pyb::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {
        // Only KeyboardInterrupt is swallowed: it becomes the interrupt a SIGINT is on the
        // command line. Another handler's exception stops the run and is raised after.
        if (PyErr_ExceptionMatches(PyExc_KeyboardInterrupt)) {
          PyErr_Clear();
          on_interrupt();
        } else {
          if (!callback_error) callback_error = std::make_unique<pyb::error_already_set>();
          stop.request(StopReason::Signal);
        }
      }
      if (!callback.is_none() && !callback_error && progress.changed) {
        double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        try {
          callback(progress_dict(progress, t));
        } catch (pyb::error_already_set& e) {
          if (e.matches(PyExc_KeyboardInterrupt)) {
            on_interrupt();
          } else {
            callback_error = std::make_unique<pyb::error_already_set>(std::move(e));
            stop.request(StopReason::Signal);
          }
        }
      }
    }
    worker.join();
  }
  // The last state, so that even a run shorter than one poll reports its end.
  if (!callback.is_none() && !callback_error && progress.changed && !failure) {
    double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    try {
      callback(progress_dict(progress, t));
    } catch (pyb::error_already_set& e) {
      if (!e.matches(PyExc_KeyboardInterrupt)) throw;
      on_interrupt();  // the run is over: nothing left to stop, but it was interrupted
    }
  }
  if (callback_error) throw std::move(*callback_error);
  if (failure) std::rethrow_exception(failure);
}

}  // namespace aspects::py
