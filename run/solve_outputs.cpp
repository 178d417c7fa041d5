#include "run/solve_outputs.h"

#include <signal.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <functional>
#include <future>
#include <fstream>
#include <iostream>

#include "io/atomic_file.h"
#include "numerics/interval.h"
#include "results/result_files.h"
#include "results/result_index.h"
#include "run/boxes_csv.h"
#include "run/checkpoint.h"
#include "search/stop_condition.h"

namespace aspects {

namespace {

// Whether process `pid` may still write its temporaries: not when it does not exist, nor
// when it has ended and its parent has not collected it yet (a zombie: the rank 0 of a
// job mpirun has just ended), which a signal 0 does not tell.
bool may_still_write(long pid) {
  if (kill(pid_t(pid), 0) != 0 && errno == ESRCH) return false;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return true;  // not ours to judge
  const size_t paren = line.rfind(')');  // the state follows the command's name
  return paren == std::string::npos || paren + 2 >= line.size() ||
         (line[paren + 2] != 'Z' && line[paren + 2] != 'X');
}

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

int remove_stale_temporaries(const std::string& dir) {
  namespace fs = std::filesystem;
  int removed = 0;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    size_t at = name.find(".tmp.");
    if (at == std::string::npos) continue;
    const std::string base = name.substr(0, at);
    if (base != "aspects.cert" && base != "aspects.cert.zst" && base != kCheckpointName &&
        base != "boxes.csv" && base != "summary.json" && base != "aspects.idx")
      continue;
    char* end = nullptr;
    long pid = std::strtol(name.c_str() + at + 5, &end, 10);
    if (pid <= 0 || end == name.c_str() + at + 5) continue;
    if (may_still_write(pid)) continue;
    removed += fs::remove(entry.path(), ec) ? 1 : 0;
  }
  return removed;
}

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
