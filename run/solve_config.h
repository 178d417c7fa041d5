// `aspects solve`: from the plan (run/solve_plan.h) to the engine's configuration: eps,
// tau, the arithmetic, the bisector, the limits and signals that stop a long run, and the
// progress display.
#pragma once

#include "generalized_aspects.h"
#include "run/solve_options.h"
#include "run/solve_progress.h"
#include "search/stop_condition.h"

namespace aspects {

// eps, tau, the links mode, the threads, the arithmetic and the bisector of resolved
// options; the certificate, limits, progress and checkpoints are attached by their own
// steps.
AspectsConfig engine_config(const SolveOptions& o);

// The limits of a long run and the signals: the search stops cleanly and the outputs
// are a partial result. The first SIGINT (Ctrl-C) stops the search and lets the phases
// after it finish on what was searched; a second one, or SIGTERM, stops the whole run; a
// third kills. Each Ctrl-C says on stderr what it does.
void set_limits(const SolveOptions& o, StopCondition& stop);

void attach_progress(SolveProgress& progress, AspectsConfig& cfg);

}  // namespace aspects
