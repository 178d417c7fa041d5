// The figure subcommands on the command line: `aspects plot`, `aspects view` and
// `aspects export`, their options and which one was chosen (aspects_main.cpp registers
// them with one call).
#pragma once

#include <CLI/CLI.hpp>

#include "plot_command.h"
#include "view_command.h"

namespace aspects {

struct FigureCommands {
  CLI::App* plot = nullptr;
  CLI::App* view = nullptr;
  CLI::App* exporter = nullptr;
  PlotOptions plot_options;
  ViewOptions view_options, export_options;
};

void add_figure_commands(CLI::App& app, FigureCommands& f);

// Whether one of them was chosen.
bool figure_command_chosen(const FigureCommands& f);

// Runs the chosen one (figure_command_chosen() must be true); its exit code.
int run_figure_command(const FigureCommands& f);

}  // namespace aspects
