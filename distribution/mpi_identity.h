// Before any work, the ranks of an MPI job agree that they run the same program on the
// same problem: the SHA-256 of the executable, of the model text and of the options that
// shape the search (eps, precision, tau, bisector, arithmetic, certificate). A rank with
// another build or another model file would send parts of another search, merged as if
// they were this one's.
#pragma once

#include <string>

#include "distribution/mpi_job.h"
#include "model/model.h"
#include "run/solve_options.h"

namespace aspects {

struct RunIdentity {
  std::string binary, model, options;  // SHA-256, hex
};

// `o` as the run will use it (after complete_options and choose_bisect).
RunIdentity identity_of(const SolveOptions& o, const Model& m);

enum class RankAgreement {
  Agreed,
  FailedOnRank0,      // rank 0 could not prepare the run (its error says why)
  FailedElsewhere,    // another rank could not (it printed why)
  DifferentBinary,
  DifferentModel,
  DifferentOptions,
};

struct Agreement {
  RankAgreement outcome = RankAgreement::Agreed;
  int rank = 0;        // the first rank that failed or differs from rank 0
  int exit_code = 0;   // of a failed rank; 2 for a difference
  std::string detail;  // rank 0 only: the two hashes that differ
};

// Collective: every rank calls it, with its identity or, when it could not prepare the run,
// null and the exit status of its error. The same outcome on every rank.
Agreement agree_on_run(MpiJob& job, const RunIdentity* mine, int failure_code);

// The message rank 0 reports for a refused run (not for FailedOnRank0).
std::string refusal_message(const Agreement& a);

}  // namespace aspects
