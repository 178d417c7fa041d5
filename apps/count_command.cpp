#include "count_command.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <thread>

#include "count_certificate.h"
#include "counting/exact_count.h"
#include "model/model.h"
#include "results/usage_error.h"
#include "run/count_dir.h"
#include "run/count_report.h"
#include "search/stop_condition.h"

namespace aspects {

namespace {

void progress_line(int round, const CountBounds& b, long cells, const long* why, void*) {
  std::fprintf(stderr,
               "count: round %d, %ld boxes, lower %d, upper %s (%ld pieces open: %ld no chart, "
               "%ld no point, %ld star failed, %ld constraint boundary; %ld adjacencies open)\n",
               round + 1, cells, b.lower, b.upper < 0 ? "none" : std::to_string(b.upper).c_str(),
               b.open_pieces, why[int(OpenReason::NoChart)], why[int(OpenReason::NoPoint)],
               why[int(OpenReason::NotStar)], why[int(OpenReason::ConstraintBoundary)],
               b.open_adjacencies);
}

}  // namespace

int run_count(const CountOptions& o) {
  if (!(o.eps > 0)) throw UsageError("--eps must be positive");
  if (!(o.min_width > 0 && o.min_width < 1)) throw UsageError("--min-width must be in (0, 1)");
  if (o.time_limit < 0) throw UsageError("--time-limit must be >= 0");
  Model m = o.model_path.empty() ? parse_model(kDefaultModelText, "(embedded RRRRR)")
                                 : load_model(o.model_path);
  if (!o.out.empty()) prepare_count_dir(o.out, "--out");
  StopCondition stop;
  if (o.time_limit > 0) stop.set_time_limit(o.time_limit);
  stop.set_watch_signals(true);
  StopSignalNotes notes;
  notes.first_interrupt =
      "\naspects: interrupted: the count stops refining and prints the certified bounds reached "
      "(Ctrl-C again to stop at once)\n";
  notes.second_interrupt = "\naspects: interrupted again: stopping now\n";
  watch_stop_signals(notes);
  CountConfig cfg;
  cfg.eps = o.eps;
  cfg.min_width = o.min_width;
  cfg.max_rounds = o.rounds;
  cfg.threads = o.threads > 0 ? o.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  cfg.stop = &stop;
  cfg.keep_records = !o.out.empty();
  if (o.progress || isatty(2)) cfg.progress = progress_line;
  std::unique_ptr<CountCertificateWriter> cert;
  if (!o.cert.empty()) {
    try {
      cert.reset(new CountCertificateWriter(o.cert, m, o.eps));
    } catch (const std::runtime_error& e) {  // an unwritable place: the option is wrong
      throw UsageError(std::string("--cert: ") + e.what());
    }
    cfg.certificate = cert->first_cover();
    cfg.first_cover_done = &CountCertificateWriter::first_cover_done;
    cfg.first_cover_data = cert.get();
  }
  CountResult r;
  try {
    r = count_aspects(m, cfg);
  } catch (const std::invalid_argument& e) {
    throw UsageError(m.file + ": " + e.what());
  }
  if (cert) cert->finish(m, r);
  if (!o.out.empty()) write_count_dir(o.out, m, r, o.eps);
  if (o.json) {
    std::cout << count_json(m, r, o.eps).dump(1) << '\n';
  } else {
    std::cout << count_line(r.bounds) << '\n';
    print_count_details(std::cout, m, r, o.eps);
  }
  return r.stop == CountStop::Stopped ? 3 : 0;
}

}  // namespace aspects
