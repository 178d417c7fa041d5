#include "run/solve_run.h"

#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <cstdio>
#include <memory>

#include "certificate_writer.h"
#include "generalized_aspects.h"
#include "run/checkpoint_saver.h"
#include "run/solve_config.h"
#include "run/solve_outputs.h"
#include "run/solve_plan.h"
#include "run/solve_progress.h"
#include "run/solve_report.h"
#include "run/subtree_stats.h"
#include "search/stop_condition.h"

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

// Hands the checkpoint's state to the engine (its finished parts are not searched again,
// the tree keeps the checkpoint's cut) and puts the certificate records of those parts
// back into `cert` (null: no certificate).
void resume_search(Checkpoint& resumed, CertificateWriter* cert, AspectsConfig& cfg) {
  SearchState& st = resumed.state;
  if (cert && st.top_done) {
    std::vector<TreeRecordFile::Mark> marks;
    for (const auto& [offset, task] : resumed.top_marks) marks.push_back({long(offset), task});
    cert->restore(-1, resumed.top_records, std::move(marks));
    for (size_t k = 0; k < st.deferred.size(); ++k)
      if (st.done[k]) cert->restore(int32_t(k), resumed.records[k]);
  }
  cfg.resume = &st;
  // Its subtrees were cut at the checkpoint's depth (a distributed run's depends on P):
  // the checkpoints this run writes say so.
  if (st.top_done) cfg.defer_depth = resumed.header.defer_depth;
}

}  // namespace

int run_solve(SolvePlan plan, const SharedSearch* shared) {
  return_large_blocks_to_system();
  const SolveOptions& o = plan.options;
  Model& model = plan.model;
  std::unique_ptr<Checkpoint>& resumed = plan.resumed;
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

int run_solve(const SolveOptions& opts) {
  return_large_blocks_to_system();  // before the plan reads the model and a checkpoint
  return run_solve(plan_solve(opts));
}

}  // namespace aspects
