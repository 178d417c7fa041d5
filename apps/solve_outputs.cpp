#include "solve_outputs.h"

#include <chrono>
#include <cstring>
#include <exception>
#include <filesystem>
#include <functional>
#include <future>
#include <iostream>

#include "boxes_csv.h"
#include "checkpoint.h"
#include "io/atomic_file.h"
#include "numerics/interval.h"
#include "result_files.h"
#include "result_index.h"
#include "search/stop_condition.h"
#include "solve_resume.h"

namespace aspects {

namespace {

// Runs `write` on a thread of its own, at the run's working precision.
std::future<void> in_thread(long precision, std::function<void()> write) {
  return std::async(std::launch::async, [precision, write] {
    set_working_precision(precision);  // a new thread starts at MPFR's default
    write();
  });
}

const char* certificate_name(const SolveOptions& o) {
  return o.compress_cert ? kCompressedCertificateName : kCertificateName;
}

// The three files that only read `r`, written concurrently: they are large (gigabytes at
// small eps) and independent. The index is written record by record on this thread, and
// ends with the certificate's hash, so it waits for the certificate last.
OutputHashes write_result_files(const SolveOptions& o, const Model& model,
                                CertificateWriter* cert, const AspectsResult& r) {
  std::future<void> certificate = in_thread(o.prec, [&] {
    if (cert) cert->finish(model, r);
  });
  std::future<void> csv =
      in_thread(o.prec, [&] { write_boxes_csv(model, r, o.out_dir + "/" + kBoxesName); });
  OutputHashes hashes;
  bool certificate_ended = false;
  std::exception_ptr failure;
  try {
    const std::string model_file = o.model_path.empty() ? "(embedded RRRRR)" : o.model_path;
    hashes.index_sha256 = write_result_index(
        o.out_dir + "/" + kResultIndexName, model, r, o.prec, o.tau, o.eps, model_file, [&] {
          certificate_ended = true;
          certificate.get();  // its failure leaves no index naming it
          if (cert) hashes.certificate = {certificate_name(o), cert->sha256()};
          return hashes.certificate;
        });
  } catch (...) {
    failure = std::current_exception();
  }
  for (std::future<void>* f : {&certificate, &csv}) {
    if (f == &certificate && certificate_ended) continue;
    try {
      f->get();
    } catch (...) {
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  return hashes;
}

// The files a run writes in its directory, and the checkpoint it may write.
void remove_previous_outputs(const SolveOptions& o) {
  namespace fs = std::filesystem;
  for (const char* name : {kCertificateName, kCompressedCertificateName, kBoxesName,
                           kResultIndexName, kSummaryName, kCheckpointName}) {
    if (!std::strcmp(name, kCheckpointName) && !o.resume_dir.empty()) continue;  // resumed
    std::error_code ec;
    fs::remove(o.out_dir + "/" + name, ec);
    if (ec)
      throw std::runtime_error("cannot remove " + o.out_dir + "/" + name +
                               " (an output of the run before): " + ec.message());
  }
  remove_stale_temporaries(o.out_dir);
}

}  // namespace

std::string output_directory(const SolveOptions& o) {
  return o.resume_dir.empty() ? o.out_dir : o.resume_dir;
}

std::unique_ptr<DirectoryLock> lock_outputs(const SolveOptions& o) {
  const std::string dir = output_directory(o);
  if (dir.empty()) return nullptr;
  // A C string ends at the NUL: "a\0b" would create and write directory a.
  if (dir.find('\0') != std::string::npos)
    throw UsageError("the output directory's path contains a NUL character");
  if (o.resume_dir.empty())
    std::filesystem::create_directories(dir);
  else if (!std::filesystem::is_directory(dir))
    return nullptr;  // reading its checkpoint will say so
  auto lock = std::make_unique<DirectoryLock>();
  switch (lock->lock(dir)) {
    case LockOutcome::Locked:
      return lock;
    case LockOutcome::Held:
      throw UsageError(dir + " is being written by another run (it holds " + dir + "/" +
                       DirectoryLock::kFileName +
                       "): wait for that run to end, or choose another output directory");
    case LockOutcome::Unsupported:
      std::cerr << "aspects: warning: cannot lock " << dir << " (" << std::strerror(lock->error())
                << "): another run writing it at the same time would mix its files\n";
      return nullptr;
    case LockOutcome::Failed:
      break;
  }
  throw std::runtime_error("cannot lock " + dir + ": cannot open " + dir + "/" +
                           DirectoryLock::kFileName + ": " + std::strerror(lock->error()));
}

std::unique_ptr<CertificateWriter> open_outputs(const SolveOptions& o, const Model& model) {
  if (o.out_dir.empty()) return nullptr;
  std::filesystem::create_directories(o.out_dir);
  remove_previous_outputs(o);
  if (o.no_cert) return nullptr;
  return std::make_unique<CertificateWriter>(o.out_dir + "/" + certificate_name(o), model, o.prec,
                                             o.tau, o.eps, o.compress_cert, o.cert_format);
}

OutputHashes write_solve_outputs(const SolveOptions& o, const Model& model,
                                 CertificateWriter* cert, AspectsResult& r) {
  const auto start = std::chrono::steady_clock::now();
  const OutputHashes hashes = write_result_files(o, model, cert, r);
  // Not in time_seconds (the solver's own time, as in the paper's Table 1).
  r.phase_seconds.emplace_back(
      "outputs", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  r.phase_peak_mib.emplace_back("outputs", peak_resident_bytes() / (1024.0 * 1024.0));
  write_file_atomically(o.out_dir + "/" + kSummaryName,
                        summary_json(model, o, r, hashes).dump(2) + "\n");
  return hashes;
}

}  // namespace aspects
