#include "solve_outputs.h"

#include <chrono>
#include <exception>
#include <filesystem>
#include <functional>
#include <future>

#include "boxes_csv.h"
#include "io/atomic_file.h"
#include "numerics/interval.h"
#include "result_index.h"
#include "search/stop_condition.h"
#include "summary_json.h"

namespace aspects {

namespace {

// Runs `write` on a thread of its own, at the run's working precision.
std::future<void> in_thread(long precision, std::function<void()> write) {
  return std::async(std::launch::async, [precision, write] {
    set_working_precision(precision);  // a new thread starts at MPFR's default
    write();
  });
}

// The three files that only read `r`, written concurrently: they are large (gigabytes at
// small eps) and independent. The index is written record by record on this thread.
void write_result_files(const SolveOptions& o, const Model& model, CertificateWriter* cert,
                        const AspectsResult& r) {
  std::future<void> certificate = in_thread(o.prec, [&] {
    if (cert) cert->finish(model, r);
  });
  std::future<void> csv =
      in_thread(o.prec, [&] { write_boxes_csv(model, r, o.out_dir + "/boxes.csv"); });
  std::exception_ptr failure;
  try {
    const std::string model_file = o.model_path.empty() ? "(embedded RRRRR)" : o.model_path;
    write_result_index(o.out_dir + "/" + kResultIndexName, model, r, o.prec, o.tau, o.eps,
                       model_file);
  } catch (...) {
    failure = std::current_exception();
  }
  for (std::future<void>* f : {&certificate, &csv}) {
    try {
      f->get();
    } catch (...) {
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace

std::unique_ptr<CertificateWriter> open_outputs(const SolveOptions& o, const Model& model) {
  if (o.out_dir.empty()) return nullptr;
  std::filesystem::create_directories(o.out_dir);
  if (o.no_cert) return nullptr;
  return std::make_unique<CertificateWriter>(
      o.out_dir + (o.compress_cert ? "/aspects.cert.zst" : "/aspects.cert"), model, o.prec, o.tau,
      o.eps, o.compress_cert, o.cert_format);
}

void write_solve_outputs(const SolveOptions& o, const Model& model, CertificateWriter* cert,
                         AspectsResult& r) {
  const auto start = std::chrono::steady_clock::now();
  write_result_files(o, model, cert, r);
  // Not in time_seconds (the solver's own time, as in the paper's Table 1).
  r.phase_seconds.emplace_back(
      "outputs", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  r.phase_peak_mib.emplace_back("outputs", peak_resident_bytes() / (1024.0 * 1024.0));
  write_file_atomically(o.out_dir + "/summary.json", summary_json(model, o, r).dump(2) + "\n");
}

}  // namespace aspects
