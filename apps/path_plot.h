// `aspects path --plot FILE`: a PNG of the workspace projection (first two pose
// coordinates) of the path's CSNC boxes with the path on top, drawn by matplotlib
// (/usr/bin/python3). An illustration only: nothing in it is a claim.
#pragma once

#include <string>

#include "loaded_result.h"
#include "path_command.h"

namespace aspects {

// Throws std::runtime_error when the figure cannot be written.
void write_path_plot(const LoadedResult& r, const PathResult& p, const std::string& png);

}  // namespace aspects
