#include "run/solve_report.h"

#include <cstdio>
#include <filesystem>

#include "search/stop_condition.h"

namespace aspects {

std::string count_line(const Model& model, const AspectsResult& r) {
  std::string line = "aspects: at least " + std::to_string(r.separation.lower_bound) +
                     " (certified lower bound";
  if (!model.user_factors.empty()) line += ", resting on the model's `factor` statements";
  return line + "; no upper bound: `aspects count` seeks one)";
}

void print_solve_report(const SolveOptions& o, const Model& model, const AspectsResult& r) {
  std::printf("robot %s  eps %g  precision %ld bits  tau %g  bisect %s\n", model.name.c_str(),
              o.eps, o.prec, o.tau, o.bisect.c_str());
  // The number of aspects first, so that nobody reads the CSNC count below as that number.
  std::printf("%s\n", count_line(model, r).c_str());
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

std::string shell_quoted(const std::string& text) {
  const bool plain = !text.empty() && text.find_first_not_of(
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./+=:,@%") ==
      std::string::npos;
  if (plain) return text;
  std::string q = "'";
  for (char c : text) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

ResumeHint resume_hint(const SolveOptions& o, CheckpointWrite last_checkpoint,
                       bool resumed_from, const std::string& checkpoint_path) {
  ResumeHint h;
  std::error_code ec;
  if (o.out_dir.empty())
    h.missing = "without --out nothing is saved";
  else if (last_checkpoint == CheckpointWrite::Written ||
           (last_checkpoint == CheckpointWrite::None && resumed_from &&
            std::filesystem::is_regular_file(checkpoint_path, ec)))
    h.command = shell_quoted(o.program) + " solve --resume " + shell_quoted(o.out_dir);
  else if (!(o.checkpoint > 0))
    h.missing = "checkpoints are off: --checkpoint 0";
  else
    h.missing = "the search had ended before a checkpoint was due";
  return h;
}

int solve_exit_status(const AspectsResult& r, CheckpointWrite last_checkpoint,
                      const ResumeHint& resume) {
  if (r.complete()) return 0;
  if (last_checkpoint == CheckpointWrite::Failed) {
    std::fprintf(stderr, "aspects: stopped by %s, but the checkpoint could not be written: "
                         "this run cannot be resumed\n", stop_reason_name(r.stopped_by));
    return 1;
  }
  // On stderr even with --quiet: scripts see exit 3, a user sees why.
  const char* why = stop_reason_name(r.stopped_by);
  if (r.unexplored > 0 && r.run_stopped_in.empty())
    std::fprintf(stderr,
                 "aspects: stopped by %s: partial result (%ld boxes unexplored; the links, "
                 "CSNCs, bound and witnesses computed on the boxes searched); every claim "
                 "above holds, the bound counts unexplored boxes like undecided ones\n",
                 why, r.unexplored);
  else if (r.unexplored > 0)
    std::fprintf(stderr,
                 "aspects: stopped by %s: partial result (%ld boxes unexplored; the phases "
                 "after the search cut from \"%s\" on: the links, CSNCs, bound and witnesses "
                 "are those established before the stop); every claim above holds, the bound "
                 "counts unexplored boxes like undecided ones\n",
                 why, r.unexplored, r.run_stopped_in.c_str());
  else
    std::fprintf(stderr,
                 "aspects: stopped by %s after the search, during \"%s\": partial result; "
                 "every claim above holds (the links, CSNCs, bound and witnesses are those "
                 "established before the stop)\n",
                 why, r.stopped_in.c_str());
  if (!resume.command.empty())
    std::fprintf(stderr, "aspects: to go on from its checkpoint: %s\n", resume.command.c_str());
  else
    std::fprintf(stderr, "aspects: no checkpoint to resume from (%s): to go on, run the whole "
                         "command again\n", resume.missing.c_str());
  return kExitStopped;
}

}  // namespace aspects
