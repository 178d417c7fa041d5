#include "solve_config.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <string>
#include <thread>

#include "numerics/interval.h"
#include "solve_resume.h"

namespace aspects {

namespace fs = std::filesystem;

namespace {

constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
// Memory still needed per output box after the search stops, for the merge, the
// neighbourhood graph, the links and the outputs (the peak minus the peak of the search,
// summary.json's phases): 123 and 128 bytes per output box on 3-RPR at eps 0.6 and 0.3
// with the certificate's link proofs, 51 without; 261 on RRRRR at eps 0.1, where the fixed
// costs weigh more (bench/RESULTS.md). tests/long_runs.py, case memory_limit, checks that a
// run stopped by the limit stays below it.
constexpr double kReservePerBox = 320;
// 2^16 subtrees: finer than any job needs (an MPI job of 1,024 processes cuts at 13).
constexpr int kMaxCutDepth = 16;

// The shortest text that reads back as x: std::to_string prints 1e-310 as 0.000000.
std::string shown(double x) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

}  // namespace

namespace {

// --cut-depth and --subtree-stats. A resumed run keeps the cut of its checkpoint and
// searches only part of the tree, so neither applies to it. The directory of the CSV is
// checked now: it is written when the run ends, perhaps hours later.
void validate_scaling_options(const SolveOptions& o) {
  if (o.cut_depth != -1 && !(o.cut_depth >= 1 && o.cut_depth <= kMaxCutDepth))
    throw UsageError("--cut-depth must be between 1 and " + std::to_string(kMaxCutDepth) +
                     " (got " + std::to_string(o.cut_depth) + ")");
  if (!o.resume_dir.empty() && (o.cut_depth != -1 || !o.subtree_stats.empty()))
    throw UsageError(std::string(o.cut_depth != -1 ? "--cut-depth" : "--subtree-stats") +
                     " is not for a resumed run (it keeps its checkpoint's cut and searches "
                     "only part of the tree)");
  if (!o.subtree_stats.empty()) {
    const fs::path dir = fs::path(o.subtree_stats).parent_path();
    std::error_code ec;
    if (!fs::is_directory(dir.empty() ? fs::path(".") : dir, ec) ||
        fs::is_directory(o.subtree_stats, ec))
      throw UsageError("--subtree-stats needs a file in an existing directory (got '" +
                       o.subtree_stats + "')");
  }
}

}  // namespace

void validate_solve_options(const SolveOptions& o) {
  if (!(o.eps > 0) || !std::isfinite(o.eps))
    throw UsageError("--eps must be a positive number (got " + shown(o.eps) + ")");
  if (!(o.tau >= 1) || !std::isfinite(o.tau))
    throw UsageError("--tau must be >= 1 (got " + shown(o.tau) + ")");
  if (o.prec < 24 || o.prec > 4096)
    throw UsageError("--prec must be between 24 and 4096 bits (got " + std::to_string(o.prec) + ")");
  if (o.threads < 0 || o.threads > 1024)
    throw UsageError("--threads must be between 0 (one per core) and 1024");
  // Sentinels are -1 (the defaults); a value the user gave must make sense.
  if (o.time_limit != -1 && !(o.time_limit > 0 && o.time_limit < 1e9))
    throw UsageError("--time-limit must be a positive number of seconds (got " +
                     shown(o.time_limit) + ")");
  if (o.max_boxes != -1 && o.max_boxes < 1)
    throw UsageError("--max-boxes must be at least 1 (got " + std::to_string(o.max_boxes) + ")");
  if (o.memory_limit != -1 && !(o.memory_limit > 0 && o.memory_limit < 1e6))
    throw UsageError("--memory-limit must be a positive number of GiB (got " +
                     shown(o.memory_limit) + ")");
  if (o.was_given("--checkpoint") && !(o.checkpoint >= 0 && o.checkpoint < 1e9))
    throw UsageError("--checkpoint must be a number of seconds, 0 for no checkpoint (got " +
                     shown(o.checkpoint) + ")");
  validate_scaling_options(o);
}

void complete_options(SolveOptions& o) {
  if (o.checkpoint > 0 && o.out_dir.empty())
    throw UsageError("--checkpoint needs --out DIR (the checkpoint is written there)");
  if (o.threads == 0) o.threads = int(std::max(1u, std::thread::hardware_concurrency()));
}

void set_precision(const SolveOptions& o) { set_working_precision(o.prec); }

Model solve_model(const SolveOptions& o, const Checkpoint* resumed) {
  if (resumed) return resumed_model(o, resumed->header);
  return o.model_path.empty() ? parse_model(kDefaultModelText, "(embedded RRRRR)")
                              : load_model(o.model_path);
}

void choose_bisect(SolveOptions& o, const Model& m) {
  if (!o.was_given("--bisect") && !m.bisect.empty()) o.bisect = m.bisect;
}

AspectsConfig engine_config(const SolveOptions& o) {
  AspectsConfig cfg;
  cfg.eps = o.eps;
  cfg.tau = o.tau;
  cfg.keep_link_proofs = !o.no_cert;
  cfg.all_links = o.all_links;
  cfg.grid_records = o.cert_format == 3;
  cfg.threads = o.threads;
  cfg.arithmetic = o.mpfi_only ? Arithmetic::MpfiOnly : Arithmetic::DoublesFirst;
  parse_bisector_kind(o.bisect, cfg.bisector);  // CLI11 already checked the name
  return cfg;
}

void set_limits(const SolveOptions& o, StopCondition& stop) {
  if (o.time_limit > 0) stop.set_time_limit(o.time_limit);
  if (o.max_boxes > 0) stop.set_max_boxes(o.max_boxes);
  if (o.memory_limit > 0) stop.set_memory_limit(o.memory_limit * kGiB, kReservePerBox);
  stop.set_watch_signals(true);
  StopSignalNotes notes;
  notes.first_interrupt =
      "\naspects: interrupted: no more boxes are searched; the links, CSNCs, bound and "
      "witnesses are finished on what was searched (Ctrl-C again to stop at once)\n";
  notes.second_interrupt =
      "\naspects: interrupted again: stopping now, with what is established so far "
      "(Ctrl-C again to kill)\n";
  watch_stop_signals(notes);
}

void attach_progress(SolveProgress& progress, AspectsConfig& cfg) {
  cfg.progress = [&progress](const SearchStats& s) { progress.tick(s); };
  cfg.phase_done = [&progress](const std::string& phase, double s) { progress.phase(phase, s); };
}

}  // namespace aspects
