// What `aspects path COUNT_DIR` and Python's aspects.piece_path report of a path through a
// count's pieces (piece_path.h): the line printed, the JSON object, and the --class option.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "piece_path.h"

namespace aspects {

// --class: one sign per determinant factor, + or -, in the factors' order; -1 for "".
// Throws UsageError naming --class.
int64_t parse_class_signs(const std::string& text, int factors);

nlohmann::json piece_path_json(const CountDirectory& d, const std::vector<double>& from,
                               const std::vector<double>& to, const PiecePathResult& r);

// The two lines printed: the robot, the count and the poses; then the outcome.
std::string piece_path_text(const CountDirectory& d, const std::vector<double>& from,
                            const std::vector<double>& to, const PiecePathResult& r);

}  // namespace aspects
