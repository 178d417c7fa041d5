// aspects._solve: the run of `aspects solve`, on a worker thread with the GIL released.
// The calling (main) thread polls every 100 ms: it runs Python's signal handlers
// (PyErr_CheckSignals), so that Ctrl-C interrupts the run's StopCondition as SIGINT does on
// the command line (the first stops the search and lets the phases after it finish on
// what was searched, the second stops them too), and the run returns a result whose
// claims all hold (aspects.solve then raises aspects.Interrupted carrying it); it also
// hands the search's progress to the Python callback. With `out`, the same files as
// `aspects solve --out` are written by the same writers (run/solve_outputs.h).
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "certificate_writer.h"
#include "generalized_aspects.h"
#include "numerics/interval.h"
#include "py_common.h"
#include "py_model.h"
#include "py_polling.h"
#include "results/result_index.h"
#include "run/solve_config.h"
#include "run/solve_outputs.h"
#include "run/solve_plan.h"
#include "run/solve_progress.h"
#include "run/summary_json.h"
#include "search/stop_condition.h"

namespace aspects::py {

namespace {

struct SolveRequest {
  double eps = 0.1, tau = 1.01, time_limit = -1;
  long prec = 53, max_boxes = -1;
  int threads = 0;
  bool all_links = false, certificate = true, compress_certificate = false, mpfi_only = false;
  std::string bisect, out;
};

// The run's plan (run/solve_plan.h), as `aspects solve` makes it, with the model's text as
// the Python object holds it.
SolvePlan plan_of(const PyModel& pm, const SolveRequest& q) {
  SolveOptions o;
  o.model_path = pm.file;
  o.eps = q.eps;
  o.tau = q.tau;
  o.prec = q.prec;
  o.threads = q.threads;
  o.time_limit = q.time_limit;
  o.max_boxes = q.max_boxes;
  o.all_links = q.all_links;
  o.mpfi_only = q.mpfi_only;
  o.no_cert = !q.certificate;
  o.compress_cert = q.compress_certificate;
  o.out_dir = q.out;
  o.quiet = true;
  if (!q.bisect.empty()) {
    if (std::find(std::begin(kBisectNames), std::end(kBisectNames), q.bisect) ==
        std::end(kBisectNames))
      throw UsageError("bisect must be round-robin, pose-first or verdict (got '" + q.bisect +
                       "')");
    o.bisect = q.bisect;
    o.given.push_back("--bisect");
  }
  validate_solve_options(o);  // its messages first, as before this check
  if (o.compress_cert && o.no_cert)
    throw UsageError("compress_certificate needs certificate=True");
  return plan_solve(o, pm.source, pm.file);
}

const InterruptNotes kSolveInterrupts = {
    "aspects.solve: interrupted: no more boxes are searched; the links, CSNCs, bound and "
    "witnesses are finished on what was searched (Ctrl-C again to stop at once)\n",
    "aspects.solve: interrupted again: stopping now, with what is established so far\n"};

pyb::tuple solve(const PyModel& pm, const SolveRequest& request, const pyb::object& callback) {
  SolvePlan plan = plan_of(pm, request);  // the output directory locked until the end
  const SolveOptions& o = plan.options;
  Model& model = plan.model;
  AspectsConfig cfg = engine_config(o);
  StopCondition stop;
  if (o.time_limit > 0) stop.set_time_limit(o.time_limit);
  if (o.max_boxes > 0) stop.set_max_boxes(o.max_boxes);
  cfg.stop = &stop;
  Progress progress;
  cfg.progress = [&progress](const SearchStats& s) {
    std::lock_guard<std::mutex> lock(progress.mu);
    progress.processed = s.processed;
    progress.solutions = s.solutions;
    progress.undecided = s.undecided;
    progress.decided = s.resumed_share + s.decided.load();
    progress.changed = true;
  };
  cfg.phase_done = [&progress](const std::string& phase, double seconds) {
    std::lock_guard<std::mutex> lock(progress.mu);
    progress.phases.emplace_back(phase, seconds);
    progress.changed = true;
  };
  std::unique_ptr<CertificateWriter> cert = open_outputs(o, model);
  cfg.certificate = cert.get();

  AspectsResult r;
  std::shared_ptr<LoadedResult> loaded;
  nlohmann::json summary;
  bool interrupted = false;
  run_polling(
      [&] {
        set_working_precision(o.prec);  // a new thread starts at MPFR's default
        r = compute_aspects(model, cfg);
        {
          // The search reports now and then; its end, from the result.
          std::lock_guard<std::mutex> lock(progress.mu);
          progress.processed = r.processed;
          progress.solutions = r.solutions;
          progress.undecided = r.undecided;
          progress.decided = decided_share(model, r);
          progress.changed = true;
        }
        OutputHashes hashes;
        if (!o.out_dir.empty()) hashes = write_solve_outputs(o, model, cert.get(), r);
        summary = summary_json(model, o, r, hashes);
        ResultIndex index = build_result_index(model, r, o.prec, o.tau, o.eps, pm.file);
        index.certificate_file = hashes.certificate.file;  // as the written index records
        index.certificate_sha256 = hashes.certificate.sha256;
        index.sha256 = hashes.index_sha256;
        loaded = std::make_shared<LoadedResult>(load_result_from(std::move(index), pm.file));
      },
      stop, progress, callback, kSolveInterrupts, interrupted);
  set_working_precision(o.prec);  // as load_result does on the thread that queries
  PyResult result{loaded, summary, o.out_dir};
  return pyb::make_tuple(pyb::cast(std::move(result)), interrupted);
}

}  // namespace

void bind_solve(pyb::module_& m) {
  m.def(
      "_solve",
      [](const PyModel& model, double eps, int threads, double time_limit, long max_boxes,
         long prec, double tau, bool all_links, const std::string& bisect,
         const std::string& out, bool certificate, bool compress_certificate, bool mpfi_only,
         const pyb::object& progress) {
        SolveRequest q;
        q.eps = eps;
        q.threads = threads;
        q.time_limit = time_limit;
        q.max_boxes = max_boxes;
        q.prec = prec;
        q.tau = tau;
        q.all_links = all_links;
        q.bisect = bisect;
        q.out = out;
        q.certificate = certificate;
        q.compress_certificate = compress_certificate;
        q.mpfi_only = mpfi_only;
        return solve(model, q, progress);
      },
      pyb::arg("model"), pyb::arg("eps"), pyb::arg("threads"), pyb::arg("time_limit"),
      pyb::arg("max_boxes"), pyb::arg("prec"), pyb::arg("tau"), pyb::arg("all_links"),
      pyb::arg("bisect"), pyb::arg("out"), pyb::arg("certificate"),
      pyb::arg("compress_certificate"), pyb::arg("mpfi_only"), pyb::arg("progress"),
      "Solve; returns (Result, interrupted). Use aspects.solve, which wraps it.");
}

}  // namespace aspects::py
