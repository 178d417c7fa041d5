// A resumed distributed run (`mpirun -n P aspects solve --resume DIR`). Rank 0 alone reads
// DIR/checkpoint (its own disk: the ranks share no filesystem) and adopts the options it
// names, as a single process does (run/solve_plan.h); the other ranks get those options
// and the model text from rank 0, so they search the problem the checkpoint belongs to,
// whatever P was when it was written.
#pragma once

#include <optional>
#include <string>

#include "distribution/mpi_job.h"
#include "run/checkpoint.h"
#include "run/solve_options.h"

namespace aspects {

// The model of a resumed run, as rank 0 sent it.
struct ResumedModel {
  std::string text, name;
};

// Whether rank 0 resumes, on every rank (collective).
bool rank0_resumes(MpiJob& job, const SolveOptions& o);

// Collective, when rank0_resumes. Rank 0: sends the options it adopted and `model` (null
// when it could not open the checkpoint: then the others get nothing). Another rank: sets
// o's eps, precision, tau, bisector, links mode, certificate and output directory from
// rank 0's, and returns the model; nothing when rank 0 failed (agree_on_run then reports
// rank 0's error). Throws on a malformed message.
std::optional<ResumedModel> share_resumed_run(MpiJob& job, SolveOptions& o,
                                              const ResumedModel* model);

}  // namespace aspects
