// `aspects plot RESULT_DIR [--out FILE] [--path FILE]`: the figure of a result, read from
// its aspects.idx (plot_data.h); --path draws on top what `aspects path --json` printed.
#pragma once

#include <string>

namespace aspects {

struct PlotOptions {
  std::string result_dir;
  std::string out;   // empty: RESULT_DIR/aspects.png
  std::string path;  // a file holding `aspects path --json` output; empty: none
};

// Exit code: 0 written; throws UsageError (2) for a bad --path file, IndexError (2) for a
// bad result directory, std::runtime_error (1) when the figure cannot be written.
int run_plot(const PlotOptions& opts);

}  // namespace aspects
