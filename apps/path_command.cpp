#include "path_command.h"

#include <sys/stat.h>

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "path_output.h"
#include "piece_path_command.h"
#include "results/count_pieces.h"
#include "results/path_plot.h"
#include "results/pose.h"
#include "results/usage_error.h"

namespace aspects {

namespace {

std::string csnc_list(const LoadedResult& r, const std::vector<int32_t>& cs) {
  std::string s;
  for (int32_t k : cs) {
    std::string sg;
    for (int8_t x : csnc_signs(r, k)) sg += x > 0 ? '+' : x < 0 ? '-' : '0';
    s += (s.empty() ? "" : ", ") + std::to_string(k) + " (signs " + sg + ")";
  }
  return s.empty() ? "none" : s;
}

void print_text(const LoadedResult& r, const PathOptions& o, const std::vector<double>& from,
                const std::vector<double>& to, const PathResult& p) {
  const Model& m = r.model;
  std::printf("robot %s  eps %g  from %s  to %s\n", m.name.c_str(), r.index.eps,
              format_pose(from).c_str(), format_pose(to).c_str());
  std::string where = "the start lies in CSNC " + csnc_list(r, p.start_csncs) +
                      "; the goal in CSNC " + csnc_list(r, p.goal_csncs);
  switch (p.outcome) {
    case PathOutcome::Found: {
      // One line: the waypoints go to --out (CSV or JSON) or --json.
      const double ratio = p.straight > 0 ? p.length / p.straight : 1;
      std::printf("certified singularity-free path in CSNC %d: %zu waypoints, length %.6g, "
                  "straight line %.6g (ratio %.3f), CSNCs crossed: 1\n",
                  p.csnc, p.waypoints.size(), p.length, p.straight, ratio);
      if (p.common_csncs.size() > 1 && o.csnc < 0)
        std::printf("other CSNCs holding both poses (other working modes): %s (use --csnc)\n",
                    csnc_list(r, {p.common_csncs.begin() + 1, p.common_csncs.end()}).c_str());
      break;
    }
    case PathOutcome::StartNowhere:
      if (o.csnc >= 0)
        std::printf("no path: the start lies in no solution box of CSNC %d; %s\n", o.csnc,
                    where.c_str());
      else
        std::printf("no path: the start lies in no solution box; %s\n", where.c_str());
      break;
    case PathOutcome::GoalNowhere:
      std::printf("no path: the goal lies in no solution box; %s\n", where.c_str());
      break;
    case PathOutcome::DifferentSigns:
      std::printf("refused: no CSNC holds both poses and their CSNCs have different determinant "
                  "signs, so they lie in different aspects: no singularity-free path joins "
                  "these configurations; %s\n", where.c_str());
      break;
    case PathOutcome::SameSignsNoPath:
      std::printf("no certified path: no CSNC holds both poses; CSNCs with equal determinant "
                  "signs may still belong to one aspect, but no certified path was found at "
                  "eps %g; %s\n", r.index.eps, where.c_str());
      break;
    case PathOutcome::ProofFailed:
      std::printf("no certified path: %s\n", p.failure.c_str());
      break;
    case PathOutcome::MembershipUnknown:
      std::printf("no certified path, and no claim: whether a pose lies in some solution box "
                  "could not be decided (a periodic coordinate too close to a face); %s\n",
                  where.c_str());
      break;
  }
}

}  // namespace

namespace {

// --out is checked before any work: a name the writer will refuse, or a missing directory.
void check_out(const std::string& out) {
  if (out.empty()) return;
  if (path_file_format(out) == PathFileFormat::Unknown)
    throw UsageError("--out: '" + out + "' must end in .csv or .json (the format written)");
  const size_t slash = out.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : out.substr(0, slash);
  struct stat st {};
  if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw UsageError("--out: the directory '" + dir + "' of '" + out + "' does not exist");
}

}  // namespace

int run_path(const PathOptions& opts) {
  // A count directory: the path runs through its pieces instead of one CSNC.
  if (is_count_directory(opts.result_dir)) return run_piece_path(opts);
  if (!opts.cls.empty())
    throw UsageError("--class needs a count directory (written by `aspects count MODEL --out "
                     "DIR`); " + opts.result_dir + " is not one (a solve's result has CSNCs: "
                     "use --csnc)");
  check_out(opts.out);
  LoadedResult r = load_result(opts.result_dir);
  if (const std::string note = certificate_note(r); !note.empty())
    std::cerr << "aspects: note: " << note << '\n';
  std::vector<double> from = parse_pose(opts.from, "--from", r.model);
  std::vector<double> to = parse_pose(opts.to, "--to", r.model);
  if (opts.csnc < -1 || (opts.csnc >= 0 && uint32_t(opts.csnc) >= r.index.csnc_count))
    throw UsageError("--csnc must be between 0 and " + std::to_string(r.index.csnc_count - 1) +
                     " (the result has " + std::to_string(r.index.csnc_count) + " CSNCs), got " +
                     std::to_string(opts.csnc));
  ModelEvaluator ev(r.model);
  PathResult p = plan_path(r, ev, from, to, opts.csnc);
  const nlohmann::json j = path_json(from, to, p);
  if (opts.json)
    std::cout << j.dump() << '\n';
  else
    print_text(r, opts, from, to, p);
  if (!opts.out.empty() && p.outcome == PathOutcome::Found)
    write_path_file(opts.out, r.model, from, to, p);
  if (!opts.out.empty() && p.outcome != PathOutcome::Found)
    std::cerr << "aspects: no path, so nothing written to " << opts.out << '\n';
  if (!opts.plot.empty() && p.outcome == PathOutcome::Found) write_path_plot(r, j, opts.plot);
  if (!opts.plot.empty() && p.outcome != PathOutcome::Found)
    std::cerr << "aspects: no path, so no figure written to " << opts.plot << '\n';
  return p.outcome == PathOutcome::Found ? 0 : 1;
}

}  // namespace aspects
