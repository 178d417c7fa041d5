// What `aspects solve` prints when the run has ended, and its exit status: 0 complete,
// kExitStopped for a run stopped by a limit or a signal (a partial result), 1 for a
// stopped run whose checkpoint could not be written (it cannot be resumed).
#pragma once

#include <string>

#include "generalized_aspects.h"
#include "model/model.h"
#include "run/checkpoint_saver.h"
#include "run/solve_options.h"

namespace aspects {

// The line that states the number of aspects a solve certifies: a lower bound only.
std::string count_line(const Model& model, const AspectsResult& r);

// The summary on stdout: options, the count line, boxes, links, CSNCs, the lower bound,
// the witnesses.
void print_solve_report(const SolveOptions& o, const Model& model, const AspectsResult& r);

// How a stopped run can go on: the exact command that resumes it from its checkpoint, or
// why there is no checkpoint to resume from.
struct ResumeHint {
  std::string command;  // empty: no checkpoint
  std::string missing;  // why, when there is none
};

// `resumed_from`: the run was resumed from `checkpoint_path` (still there unless this run
// replaced it).
ResumeHint resume_hint(const SolveOptions& o, CheckpointWrite last_checkpoint,
                       bool resumed_from, const std::string& checkpoint_path);

// The exit status; a stopped run says on stderr why, and how to go on (even with --quiet).
int solve_exit_status(const AspectsResult& r, CheckpointWrite last_checkpoint,
                      const ResumeHint& resume);

// `text` quoted for a POSIX shell when it needs to be.
std::string shell_quoted(const std::string& text);

}  // namespace aspects
