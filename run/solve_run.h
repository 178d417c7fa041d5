// The run of `aspects solve`: its plan (run/solve_plan.h) handed to the engine, the
// checkpoints, the progress and the limits attached, then the outputs and the report.
#pragma once

#include "run/solve_options.h"
#include "run/solve_plan.h"

namespace aspects {

class RemoteSubtrees;

// A search shared with other processes: the distribution's side of the run (an MPI job's
// rank 0: distribution/mpi_solve.*). Who searches the other subtrees, where the tree is
// cut into them (a resumed state keeps its checkpoint's cut), and the threads of the
// phases after the search.
struct SharedSearch {
  RemoteSubtrees* remote;
  int defer_depth;
  int later_threads = 0;  // 0: --threads
};

// Runs the plan; returns the exit status (0 complete, kExitStopped, 1 a stopped run that
// cannot be resumed). The plan's lock is held to the end.
int run_solve(SolvePlan plan, const SharedSearch* shared = nullptr);

// plan_solve(opts), then run it: `aspects solve` in a single process.
int run_solve(const SolveOptions& opts);

}  // namespace aspects
