#include "run/solve_plan.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

#include "aspects_version.h"
#include "numerics/interval.h"
#include "run/solve_outputs.h"

namespace aspects {

namespace fs = std::filesystem;

namespace {

// 2^16 subtrees: finer than any job needs (an MPI job of 1,024 processes cuts at 13).
constexpr int kMaxCutDepth = 16;

// The shortest text that reads back as x: std::to_string prints 1e-310 as 0.000000.
std::string shown(double x) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

// 17 digits, as a checkpoint's values are compared in the messages of a resumed run.
std::string show(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

template <class T>
void adopt(const SolveOptions& o, const char* name, T& value, const T& saved,
           const std::string& value_text, const std::string& saved_text) {
  if (o.was_given(name) && !(value == saved))
    throw CheckpointError("--resume: " + std::string(name) + " " + value_text +
                          " differs from the checkpoint's " + saved_text +
                          " (give the same value, or leave the option out)");
  value = saved;
}

// The model of the resumed run: MODEL when given again (its text must hash as the
// checkpoint's), else the model text the checkpoint holds.
Model resumed_model(const SolveOptions& o, const CheckpointHeader& h) {
  if (!o.was_given("MODEL"))
    return parse_model(h.model_text, h.model_file.empty() ? "(embedded RRRRR)" : h.model_file);
  Model m = load_model(o.model_path);
  if (sha256_hex(m.source) != h.model_sha256)
    throw CheckpointError("--resume: " + o.model_path +
                          " is not the model the checkpoint was made for (its text differs; "
                          "leave MODEL out to use the checkpoint's)");
  return m;
}

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

void adopt_checkpoint(SolveOptions& o, const CheckpointHeader& h) {
  if (h.version != ASPECTS_VERSION_FULL)
    throw CheckpointError("--resume: the checkpoint was written by aspects " + h.version +
                          ", this is aspects " ASPECTS_VERSION_FULL
                          ": a state is resumed only by the program that wrote it");
  adopt(o, "--eps", o.eps, h.eps, show(o.eps), show(h.eps));
  long prec = long(h.precision);
  adopt(o, "--prec", o.prec, prec, std::to_string(o.prec), std::to_string(prec));
  adopt(o, "--tau", o.tau, h.tau, show(o.tau), show(h.tau));
  adopt(o, "--bisect", o.bisect, h.bisect, o.bisect, h.bisect);
  auto flag = [](bool b) { return std::string(b ? "given" : "not given"); };
  bool all_links = h.all_links, no_cert = h.no_cert;
  adopt(o, "--all-links", o.all_links, all_links, flag(o.all_links), flag(all_links));
  adopt(o, "--no-cert", o.no_cert, no_cert, flag(o.no_cert), flag(no_cert));
  int format = h.cert_format;
  adopt(o, "--cert-format", o.cert_format, format, std::to_string(o.cert_format),
        std::to_string(format));
  if (o.was_given("--out") && fs::weakly_canonical(o.out_dir) != fs::weakly_canonical(o.resume_dir))
    throw UsageError("--out " + o.out_dir + " differs from --resume " + o.resume_dir +
                     " (a resumed run writes where it was stopped)");
  o.out_dir = o.resume_dir;
  if (!o.was_given("--checkpoint")) o.checkpoint = h.checkpoint_seconds;
  if (!o.was_given("MODEL")) o.model_path = h.model_file;
}

std::unique_ptr<Checkpoint> open_resumed_run(SolveOptions& o) {
  if (o.resume_dir.empty()) return nullptr;
  auto resumed =
      std::make_unique<Checkpoint>(read_checkpoint(o.resume_dir + "/" + kCheckpointName));
  adopt_checkpoint(o, resumed->header);
  remove_stale_temporaries(o.out_dir);  // a killed run's
  return resumed;
}

SolvePlan plan_solve(const SolveOptions& given) {
  validate_solve_options(given);
  SolvePlan plan;
  SolveOptions& o = plan.options;
  o = given;
  plan.lock = lock_outputs(o);  // before its checkpoint is read
  // Resuming: the options and the model come from the checkpoint (checked against any
  // given again); the parts it holds are not searched again.
  plan.resumed = open_resumed_run(o);
  // A single process checkpoints by default (a resumed run keeps its checkpoint's interval).
  if (!plan.resumed && !o.was_given("--checkpoint") && !o.out_dir.empty())
    o.checkpoint = kDefaultCheckpointSeconds;
  complete_options(o);
  set_precision(o);
  plan.model = solve_model(o, plan.resumed.get());
  if (!plan.resumed) choose_bisect(o, plan.model);
  return plan;
}

SolvePlan plan_solve(const SolveOptions& given, const std::string& model_text,
                     const std::string& model_name) {
  validate_solve_options(given);
  SolvePlan plan;
  SolveOptions& o = plan.options;
  o = given;
  if (!o.resume_dir.empty()) throw UsageError("a front end's own model is not resumed");
  complete_options(o);
  set_precision(o);  // this thread's precision: the model's intervals are made here
  plan.model = parse_model(model_text, model_name);
  choose_bisect(o, plan.model);
  plan.lock = lock_outputs(o);
  return plan;
}

}  // namespace aspects
