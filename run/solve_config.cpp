#include "run/solve_config.h"

#include <string>

namespace aspects {

namespace {

constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
// Memory still needed per output box after the search stops, for the merge, the
// neighbourhood graph, the links and the outputs (the peak minus the peak of the search,
// summary.json's phases): 123 and 128 bytes per output box on 3-RPR at eps 0.6 and 0.3
// with the certificate's link proofs, 51 without; 261 on RRRRR at eps 0.1, where the fixed
// costs weigh more (bench/RESULTS.md). tests/long_runs.py, case memory_limit, checks that a
// run stopped by the limit stays below it.
constexpr double kReservePerBox = 320;

}  // namespace

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
