// `aspects solve`: from the command's options to the engine's configuration: the checked
// option values, the arithmetic, the model, the bisector, the limits and signals that stop
// a long run, and the progress display.
#pragma once

#include "checkpoint.h"
#include "generalized_aspects.h"
#include "model/model.h"
#include "search/stop_condition.h"
#include "solve_command.h"
#include "solve_progress.h"

namespace aspects {

// Throws UsageError naming the first option whose value makes no sense.
void validate_solve_options(const SolveOptions& o);

// The values left to the program: the thread count (one per core). Throws UsageError
// for --checkpoint without --out.
void complete_options(SolveOptions& o);

// This thread's working precision (each thread of the run sets its own: MPFR keeps it per
// thread). The rest of the arithmetic is the engine's configuration (engine_config).
void set_precision(const SolveOptions& o);

// The model to solve: the resumed run's, MODEL, or the embedded RRRRR.
Model solve_model(const SolveOptions& o, const Checkpoint* resumed);

// The model's `bisect` statement chooses unless --bisect is given (not for a resumed run:
// it has the one its checkpoint names).
void choose_bisect(SolveOptions& o, const Model& m);

// eps, tau, the links mode, the threads and the bisector; the certificate, limits,
// progress and checkpoints are attached by their own steps.
AspectsConfig engine_config(const SolveOptions& o);

// The limits of a long run and the signals: the search stops cleanly and the outputs
// are a partial result. The first SIGINT (Ctrl-C) stops the search and lets the phases
// after it finish on what was searched; a second one, or SIGTERM, stops the whole run; a
// third kills. Each Ctrl-C says on stderr what it does.
void set_limits(const SolveOptions& o, StopCondition& stop);

void attach_progress(SolveProgress& progress, AspectsConfig& cfg);

}  // namespace aspects
