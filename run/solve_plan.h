// A solve's plan: its options resolved once, before anything runs, into everything the run
// needs (the model, the arithmetic and precision, the limits, the outputs and their lock,
// and the checkpoint of a resumed run), then passed forward to the engine's configuration
// (run/solve_config.h), the checkpoints, the outputs and the report, which only read it.
//
// Resolving, in order: the values are checked (UsageError, exit 2); the output directory
// is locked; with --resume DIR its checkpoint is read and the run's options are taken from
// its header (an option given again must agree: CheckpointError, exit 2, so that a state is
// never mixed with another model, eps, precision or program version); the defaults left
// to the program are filled in; the working precision is set; the model is read; the
// model's `bisect` statement chooses the bisector unless --bisect is given.
#pragma once

#include <memory>

#include "io/directory_lock.h"
#include "model/model.h"
#include "run/checkpoint.h"
#include "run/solve_options.h"

namespace aspects {

struct SolvePlan {
  SolveOptions options;  // resolved: nothing after the plan changes them
  Model model;
  std::unique_ptr<Checkpoint> resumed;  // null: not resumed
  // The output directory's lock, held for the whole run: another run writing the
  // directory would mix its files with ours (null: no directory, or no locks there).
  std::unique_ptr<DirectoryLock> lock;
};

// The plan of a single process's `aspects solve`: the model from MODEL, the embedded RRRRR
// or the checkpoint; a checkpoint every kDefaultCheckpointSeconds with --out unless
// --checkpoint says otherwise.
SolvePlan plan_solve(const SolveOptions& given);

// The plan of a front end that holds its model's text already (aspects.solve): no
// --resume, and no checkpoint unless asked for. The text is parsed once the precision is
// set (the model's constants are intervals of it).
SolvePlan plan_solve(const SolveOptions& given, const std::string& model_text,
                     const std::string& model_name);

// The steps of the plan, for a run that interleaves them with other work (an MPI job
// agrees on each rank's before it goes on: distribution/mpi_solve.cpp).

// Throws UsageError naming the first option whose value makes no sense.
void validate_solve_options(const SolveOptions& o);

// With --resume DIR: reads DIR's checkpoint, takes the run's options from it (see
// adopt_checkpoint) and removes the temporaries a killed run left there. Null without
// --resume. Take the output directory's lock first.
std::unique_ptr<Checkpoint> open_resumed_run(SolveOptions& o);

// Sets o's eps, precision, tau, bisector, links mode, certificate, output directory and
// checkpoint interval from h (refusing a version or explicit option that differs).
void adopt_checkpoint(SolveOptions& o, const CheckpointHeader& h);

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

}  // namespace aspects
