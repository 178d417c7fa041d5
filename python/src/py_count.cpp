// aspects.count: the certified number of aspects, or bounds on it (proofs/counting/), as
// `aspects count --json` reports it (run/count_report.h).
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "counting/exact_count.h"
#include "model/model.h"
#include "py_common.h"
#include "py_model.h"
#include "run/count_report.h"
#include "search/stop_condition.h"

namespace aspects::py {

namespace {

// The count on a worker thread, the caller's thread polling Python's signals: Ctrl-C stops
// the refinement, and the bounds reached (which hold) are returned, as on the command line.
pyb::tuple count(const PyModel& pm, const CountConfig& given, double time_limit) {
  Model m = parse_model(pm.source, pm.file);
  StopCondition stop;
  if (time_limit > 0) stop.set_time_limit(time_limit);
  CountConfig cfg = given;
  cfg.stop = &stop;
  CountResult r;
  bool interrupted = false;
  std::mutex mu;
  std::condition_variable cv;
  bool done = false;
  std::exception_ptr failure;
  {
    pyb::gil_scoped_release release;
    std::thread worker([&] {
      try {
        r = count_aspects(m, cfg);
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
        if (!PyErr_ExceptionMatches(PyExc_KeyboardInterrupt)) {
          stop.interrupt();
          stop.interrupt();  // a second one: stop at once
          worker.join();
          throw pyb::error_already_set();
        }
        PyErr_Clear();
        interrupted = true;
        stop.interrupt();  // any stop ends the refinement (a first one, the first cover's search)
      }
    }
    worker.join();
  }
  if (failure) {
    try {
      std::rethrow_exception(failure);
    } catch (const std::invalid_argument& e) {  // a refused model: named as the CLI names it
      throw std::invalid_argument(m.file + ": " + e.what());
    }
  }
  return pyb::make_tuple(to_python(count_json(m, r, cfg.eps)),
                         pyb::str(count_line(r.bounds)), interrupted);
}

}  // namespace

void bind_count(pyb::module_& m) {
  m.def(
      "_count",
      [](const PyModel& model, double eps, double min_width, int rounds, double time_limit,
         int threads) {
        CountConfig cfg;
        cfg.eps = eps;
        cfg.min_width = min_width;
        cfg.max_rounds = rounds;
        cfg.threads = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
        return count(model, cfg, time_limit);
      },
      pyb::arg("model"), pyb::arg("eps"), pyb::arg("min_width"), pyb::arg("rounds"),
      pyb::arg("time_limit"), pyb::arg("threads"),
      "Count; returns (count --json's object, the count line, interrupted). Use aspects.count.");
}

}  // namespace aspects::py
