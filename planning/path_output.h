// `aspects path --out FILE`: the waypoints of a found path, as CSV (FILE ends in .csv) or
// JSON (.json, what --json prints), written under a temporary name and renamed.
#pragma once

#include <string>

#include "path_plan.h"

namespace aspects {

enum class PathFileFormat { Csv, Json, Unknown };

// By the file's extension (case-insensitive).
PathFileFormat path_file_format(const std::string& file);

// CSV: a header `kind,<pose variables>,<command variables>_lo,..._hi,...,box`, then one row
// per waypoint, the pose unwrapped (pose + 2π·turns, rounded to double) and every number
// written with 17 significant digits. Throws std::runtime_error when it cannot be written.
void write_path_file(const std::string& file, const Model& m, const std::vector<double>& from,
                     const std::vector<double>& to, const PathResult& p);

}  // namespace aspects
