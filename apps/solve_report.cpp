#include "solve_report.h"

#include <cstdio>

#include "search/stop_condition.h"

namespace aspects {

void print_solve_report(const SolveOptions& o, const Model& model, const AspectsResult& r) {
  std::printf("robot %s  eps %g  precision %ld bits  tau %g  bisect %s\n", model.name.c_str(),
              o.eps, o.prec, o.tau, o.bisect.c_str());
  if (r.complete())
    std::printf("boxes: %d (%ld solution, %ld undecided)\n", r.boxes.size(), r.solutions,
                r.undecided);
  else
    std::printf("boxes: %d (%ld solution, %ld undecided, %ld unexplored)\n",
                r.boxes.size(), r.solutions, r.undecided, r.unexplored);
  std::printf("links: %zu neighbour pairs, %zu certified\n", r.neighbor_count,
              r.certified_links.size());
  std::printf("CSNCs: %zu, filtered: %d\n", r.csnc_sizes.size(), r.filtered);
  std::printf("separated lower bound on the number of aspects: %d\n", r.separation.lower_bound);
  std::printf("cuspidality witnesses: %zu one pose/two commands, %zu one command/two poses\n",
              r.cuspidal.pose.size(), r.cuspidal.command.size());
  std::printf("time: %.3f s\n", r.seconds);
}

int solve_exit_status(const AspectsResult& r, CheckpointWrite last_checkpoint) {
  if (r.complete()) return 0;
  if (last_checkpoint == CheckpointWrite::Failed) {
    std::fprintf(stderr, "aspects: stopped by %s, but the checkpoint could not be written: "
                         "this run cannot be resumed\n", stop_reason_name(r.stopped_by));
    return 1;
  }
  // On stderr even with --quiet: scripts see exit 3, a user sees why.
  if (r.unexplored > 0)
    std::fprintf(stderr,
                 "aspects: stopped by %s: partial result (%ld boxes unexplored); every claim "
                 "above holds, the bound counts unexplored boxes like undecided ones\n",
                 stop_reason_name(r.stopped_by), r.unexplored);
  else
    std::fprintf(stderr,
                 "aspects: stopped by %s after the search, during \"%s\": partial result; "
                 "every claim above holds (the links, CSNCs, bound and witnesses are those "
                 "established before the stop)\n",
                 stop_reason_name(r.stopped_by), r.stopped_in.c_str());
  return kExitStopped;
}

}  // namespace aspects
