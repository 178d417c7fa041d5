// `aspects solve` in an MPI job (`mpirun -n P aspects solve ...`, built with
// -DASPECTS_MPI=ON). Every rank prepares the run from the same command line and the ranks
// agree that they run the same executable, model and options (distribution/mpi_identity.h). Rank 0
// then runs `aspects solve` as one process would, except that its deferred subtrees are
// searched by every rank (distribution/mpi_subtrees.h); it alone merges the parts in depth-first
// order and runs the later phases and the outputs, so the result is the one a single
// process writes, for any P. With P = 1 it is the plain run.
#pragma once

#include "distribution/mpi_job.h"
#include "run/solve_options.h"

namespace aspects {

// This rank's exit status: rank 0's run's, on every rank. Errors of rank 0 are thrown (as
// from run_solve); another rank reports its own and ends the job.
int run_solve_mpi(const SolveOptions& opts, MpiJob& job);

}  // namespace aspects
