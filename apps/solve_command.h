// `aspects solve`: its options on the command line. The run itself is the library's
// (run/solve_plan.h resolves the options once, run/solve_run.h runs the plan and prints
// the report).
#pragma once

#include <CLI/CLI.hpp>

#include "run/solve_options.h"

namespace aspects {

struct SolveCommand {
  CLI::App* app = nullptr;
  SolveOptions options;
};

void add_solve_command(CLI::App& app, SolveCommand& c);

// Records in c.options.given the options of `solve` given on the command line: a resumed
// run refuses those that differ from its checkpoint, and the model's `bisect` statement
// yields to --bisect.
void record_given_options(SolveCommand& c);

}  // namespace aspects
