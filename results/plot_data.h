// Figures of a result (`aspects plot`, `view`, `export`, `path --plot`): the boxes are
// handed to the project's one plotting code, python/aspects/plotting.py, run by
// /usr/bin/python3 (matplotlib; plotly and scikit-image for `view`; meshio for `export`),
// with the run's certified count from summary.json. An illustration only: nothing in it
// is a claim but that count, said as what it is.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "results/loaded_result.h"

namespace aspects {

// plotting.py next to this program: the build tree's build/python/aspects/, or the
// installed P/lib/python3/dist-packages/aspects/ for P/bin/aspects. Empty when neither.
std::string find_plotting_script();

// Writes `out` (through a temporary name): the CSNCs and undecided boxes of `r`, and
// `path` on top when it is not null (what `aspects path --json` prints). `figure`: the
// figure's kind and options (figure_options.h's figure_json). Throws std::runtime_error
// when the figure cannot be written.
void write_result_figure(const LoadedResult& r, const nlohmann::json& path,
                         const nlohmann::json& figure, const std::string& out);

// write_result_figure's default plot (`aspects path --plot`).
void write_result_plot(const LoadedResult& r, const nlohmann::json& path, const std::string& png);

// The certified count the figures state (summary.json beside the index): "lower_bound"
// and "representatives", empty when the directory has no summary.
nlohmann::json certified_count_json(const LoadedResult& r);

}  // namespace aspects
