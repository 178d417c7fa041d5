// `aspects plot RESULT_DIR [--out FILE] [--path FILE] [figure options]`: the figure of a
// result, read from its aspects.idx (plot_data.h); --path draws on top what `aspects path
// --json` printed; the figure options (figure_options.h) choose axes, CSNCs, dpi, size.
#pragma once

#include <string>

#include "figure_options.h"

namespace aspects {

struct PlotOptions {
  std::string result_dir;
  std::string out;   // empty: RESULT_DIR/aspects.png
  std::string path;  // a file holding `aspects path --json` output; empty: none
  FigureOptions figure;
};

// Exit code: 0 written; throws UsageError (2) for a bad --path file or figure option,
// IndexError (2) for a bad result directory, std::runtime_error (1) when the figure cannot be written.
int run_plot(const PlotOptions& opts);

}  // namespace aspects
