// `aspects path --plot FILE`: the result's figure (plot_data.h: the CSNCs projected on the
// pose, then the path's CSNC alone) with the path on top. An illustration only: nothing in
// it is a claim.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "results/loaded_result.h"

namespace aspects {

// `path`: what `aspects path --json` prints. Throws std::runtime_error when the figure
// cannot be written.
void write_path_plot(const LoadedResult& r, const nlohmann::json& path, const std::string& png);

}  // namespace aspects
