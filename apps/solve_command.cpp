#include "solve_command.h"

#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <cstdio>
#include <memory>

#include "certificate_writer.h"
#include "checkpoint_saver.h"
#include "generalized_aspects.h"
#include "search/stop_condition.h"
#include "solve_config.h"
#include "solve_outputs.h"
#include "solve_progress.h"
#include "solve_report.h"
#include "solve_resume.h"
#include "subtree_stats.h"

namespace aspects {

namespace {

double resident_mib() { return resident_bytes() / (1024.0 * 1024.0); }

// Blocks from 1 MiB up in their own mappings, returned to the system when freed. glibc's
// default threshold rises with every large block freed, after which the search parts'
// arrays, freed one by one as they are merged, would stay in the heap and raise the peak.
void return_large_blocks_to_system() {
#ifdef __GLIBC__
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
}

}  // namespace

int run_solve(const SolveOptions& opts, SharedSearch* shared) {
  validate_solve_options(opts);
  return_large_blocks_to_system();
  SolveOptions o = opts;
  // Held to the end: another run writing the directory would mix its files with ours.
  const std::unique_ptr<DirectoryLock> lock = shared ? std::move(shared->lock) : lock_outputs(o);
  // Resuming: the options and the model come from the checkpoint (checked against any
  // given again); the parts it holds are not searched again.
  std::unique_ptr<Checkpoint> resumed = shared ? std::move(shared->resumed) : open_resumed_run(o);
  // A single process checkpoints by default (a resumed run keeps its checkpoint's interval).
  if (!shared && !resumed && !o.was_given("--checkpoint") && !o.out_dir.empty())
    o.checkpoint = kDefaultCheckpointSeconds;
  complete_options(o);
  set_precision(o);
  Model model = shared ? std::move(*shared->model) : solve_model(o, resumed.get());
  if (!resumed) choose_bisect(o, model);

  AspectsConfig cfg = engine_config(o);
  if (shared) {
    cfg.remote = shared->remote;
    cfg.defer_depth = shared->defer_depth;
    cfg.later_threads = shared->later_threads;
  }
  if (o.cut_depth != -1) cfg.defer_depth = o.cut_depth;
  std::unique_ptr<SubtreeStats> subtree_stats;
  if (!o.subtree_stats.empty()) {
    subtree_stats = std::make_unique<SubtreeStats>(o.subtree_stats);
    subtree_stats->attach(cfg);
  }
  StopCondition stop;
  set_limits(o, stop);
  cfg.stop = &stop;
  const bool tty = isatty(STDERR_FILENO);
  const bool show_progress = o.progress || tty;
  SolveProgress progress(tty);
  if (show_progress) attach_progress(progress, cfg);
  std::unique_ptr<CertificateWriter> cert = open_outputs(o, model);
  cfg.certificate = cert.get();
  if (resumed) resume_search(*resumed, cert.get(), cfg);
  CheckpointSaver checkpoints(o);
  checkpoints.attach(o, model, cfg, cert.get());

  AspectsResult r = compute_aspects(model, cfg);
  if (subtree_stats) subtree_stats->write();
  if (show_progress) progress.done(model, r, resident_mib());
  if (!o.out_dir.empty()) write_solve_outputs(o, model, cert.get(), r);
  if (!o.quiet) print_solve_report(o, model, r);
  if (r.complete() && !o.out_dir.empty()) std::remove(checkpoints.path().c_str());  // done with it
  return solve_exit_status(
      r, checkpoints.last_write(),
      resume_hint(o, checkpoints.last_write(), resumed != nullptr, checkpoints.path()));
}

}  // namespace aspects
