// aspects.count: the certified number of aspects, or bounds on it (proofs/counting/), as
// `aspects count --json` reports it (run/count_report.h).
#include <stdexcept>
#include <thread>

#include "counting/exact_count.h"
#include "model/model.h"
#include "py_common.h"
#include "py_model.h"
#include "py_polling.h"
#include "run/count_report.h"
#include "search/stop_condition.h"

namespace aspects::py {

namespace {

const InterruptNotes kCountInterrupts = {
    "aspects.count: interrupted: the refinement stops and the certified bounds reached are "
    "returned (Ctrl-C again to stop at once)\n",
    "aspects.count: interrupted again: stopping now\n"};

// The count on a worker thread (py_polling.h): Ctrl-C stops the refinement, and the bounds
// reached (which hold) are returned, as on the command line.
pyb::tuple count(const PyModel& pm, const CountConfig& given, double time_limit) {
  Model m = parse_model(pm.source, pm.file);
  StopCondition stop;
  if (time_limit > 0) stop.set_time_limit(time_limit);
  CountConfig cfg = given;
  cfg.stop = &stop;
  CountResult r;
  bool interrupted = false;
  Progress none;  // no progress callback
  try {
    run_polling([&] { r = count_aspects(m, cfg); }, stop, none, pyb::none(), kCountInterrupts,
                interrupted);
  } catch (const std::invalid_argument& e) {  // a refused model: named as the CLI names it
    throw std::invalid_argument(m.file + ": " + e.what());
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
