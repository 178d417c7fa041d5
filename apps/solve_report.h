// What `aspects solve` prints when the run has ended, and its exit status: 0 complete,
// kExitStopped for a run stopped by a limit or a signal (a partial result), 1 for a
// stopped run whose checkpoint could not be written (it cannot be resumed).
#pragma once

#include "checkpoint_saver.h"
#include "generalized_aspects.h"
#include "model/model.h"
#include "solve_command.h"

namespace aspects {

// The summary on stdout: options, boxes, links, CSNCs, the lower bound, the witnesses.
void print_solve_report(const SolveOptions& o, const Model& model, const AspectsResult& r);

// The exit status; a stopped run says on stderr why (even with --quiet).
int solve_exit_status(const AspectsResult& r, CheckpointWrite last_checkpoint);

}  // namespace aspects
