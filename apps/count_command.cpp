#include "count_command.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "count_certificate.h"
#include "counting/exact_count.h"
#include "model/model.h"
#include "search/stop_condition.h"
#include "solve_command.h"

namespace aspects {

namespace {

std::string class_text(uint32_t cls, int p) {
  std::string s;
  for (int i = 0; i < p; ++i) s += (cls >> i) & 1 ? '+' : '-';
  return s;
}

std::string box_text(const OpenPlace& o, const Model& m) {
  std::ostringstream out;
  out.precision(6);
  for (size_t v = 0; v < o.lo.size(); ++v)
    out << (v ? ", " : "") << m.vars[v].name << " in [" << o.lo[v] << ", " << o.hi[v] << "]";
  return out.str();
}

void progress_line(int round, const CountBounds& b, long cells, const long* why, void*) {
  std::fprintf(stderr,
               "count: round %d, %ld boxes, lower %d, upper %s (%ld pieces open: %ld no chart, "
               "%ld no point, %ld star failed; %ld adjacencies open)\n",
               round + 1, cells, b.lower, b.upper < 0 ? "none" : std::to_string(b.upper).c_str(),
               b.open_pieces, why[int(OpenReason::NoChart)], why[int(OpenReason::NoPoint)],
               why[int(OpenReason::NotStar)], b.open_adjacencies);
}

}  // namespace

int run_count(const CountOptions& o) {
  if (!(o.eps > 0)) throw UsageError("--eps must be positive");
  if (!(o.min_width > 0 && o.min_width < 1)) throw UsageError("--min-width must be in (0, 1)");
  if (o.time_limit < 0) throw UsageError("--time-limit must be >= 0");
  Model m = o.model_path.empty() ? parse_model(kDefaultModelText, "(embedded RRRRR)")
                                 : load_model(o.model_path);
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
  cfg.threads = o.threads > 0 ? o.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  cfg.stop = &stop;
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
  const CountBounds& b = r.bounds;
  const int p = int(r.factor_text.size());
  std::string line;
  auto aspects = [](int k) { return std::to_string(k) + (k == 1 ? " aspect" : " aspects"); };
  if (b.exact())
    line = aspects(b.lower) + " (certified: lower = upper)";
  else if (b.upper >= 0)
    line = "between " + std::to_string(b.lower) + " and " + aspects(b.upper) + " (certified)";
  else
    line = "at least " + aspects(b.lower) + " (certified); no upper bound: " +
           std::to_string(b.open_pieces) + " piece(s) not proved connected";
  if (o.json) {
    nlohmann::json j;
    j["robot"] = m.name;
    j["lower_bound"] = b.lower;
    j["upper_bound"] = b.upper < 0 ? nlohmann::json(nullptr) : nlohmann::json(b.upper);
    j["exact"] = b.exact();
    j["stop"] = count_stop_name(r.stop);
    j["open_pieces"] = b.open_pieces;
    j["open_adjacencies"] = b.open_adjacencies;
    j["open_pieces_by_reason"] = {{"no_chart", r.open_by_reason[int(OpenReason::NoChart)]},
                                  {"no_point", r.open_by_reason[int(OpenReason::NoPoint)]},
                                  {"not_star", r.open_by_reason[int(OpenReason::NotStar)]},
                                  {"not_reached", r.open_by_reason[int(OpenReason::NotReached)]}};
    j["first_cover"] = {{"eps", o.eps}, {"boxes", r.first_cover_boxes},
                        {"separated_lower_bound", r.separation_bound}};
    j["boxes"] = r.cells;
    j["pieces"] = r.pieces;
    j["adjacencies"] = r.adjacencies;
    j["bisections"] = r.bisections;
    j["rounds"] = r.rounds;
    j["seconds"] = r.seconds;
    j["factors"] = r.factor_text;
    nlohmann::json open = nlohmann::json::array();
    for (const OpenPlace& pl : r.open)
      open.push_back({{"reason", open_reason_name(pl.reason)}, {"class", class_text(pl.cls, p)},
                      {"lo", pl.lo}, {"hi", pl.hi}});
    j["open"] = open;
    std::cout << j.dump(1) << '\n';
  } else {
    std::cout << line << '\n';
    std::cout << "robot " << m.name << "  first cover eps " << o.eps << " (" << r.first_cover_boxes
              << " boxes, separated lower bound " << r.separation_bound << "), then "
              << r.bisections << " bisections where a bound could move\n";
    std::cout << "boxes: " << r.cells << ", pieces: " << r.pieces << ", adjacencies: "
              << r.adjacencies << ", rounds: " << r.rounds << ", " << r.seconds << " s\n";
    std::cout << "sign classes over:";
    for (const std::string& f : r.factor_text) std::cout << "  " << f;
    std::cout << '\n';
    if (!b.exact()) {
      std::cout << "the gap is held by " << b.open_pieces << " piece(s) not proved connected ("
                << r.open_by_reason[int(OpenReason::NoChart)] << " with no chart, "
                << r.open_by_reason[int(OpenReason::NoPoint)] << " with no certified point, "
                << r.open_by_reason[int(OpenReason::NotStar)] << " whose star test failed, "
                << r.open_by_reason[int(OpenReason::NotReached)] << " not decided before the stop) and "
                << b.open_adjacencies << " undecided adjacency(ies) between components; "
                << "the refinement ended: " << count_stop_name(r.stop) << '\n';
      for (const OpenPlace& pl : r.open)
        std::cout << "  class " << class_text(pl.cls, p) << ": " << open_reason_name(pl.reason)
                  << ", at " << box_text(pl, m) << '\n';
    }
  }
  return r.stop == CountStop::Stopped ? 3 : 0;
}

}  // namespace aspects
