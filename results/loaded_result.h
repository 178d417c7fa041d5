// A result directory opened for `aspects query` and `aspects path`: the index of
// result_index.h and its model parsed again from the recorded text, at the recorded
// working precision. Pose coordinates are in pose order (the model's pose variables in
// declaration order).
#pragma once

#include <string>
#include <vector>

#include "model/model.h"
#include "results/result_index.h"

namespace aspects {

struct LoadedResult {
  ResultIndex index;
  Model model;
  std::vector<bool> pose_periodic;  // pose order
  std::string directory;            // where it was read from (empty: built in memory)
};

// Reads DIR/aspects.idx and parses its model. Sets the working precision to the
// recorded one, so call it before creating any interval. Throws IndexError, also when a
// certificate or summary.json in DIR is not of the run that wrote the index
// (result_files.h: a stale or mixed directory).
LoadedResult load_result(const std::string& result_dir);

// What a reader of the result should know of its certificate: empty when the index
// records one; else that nothing of the result was checked by check_cert.
std::string certificate_note(const LoadedResult& r);

// Builds the same from an index already in memory (tests); throws IndexError.
LoadedResult load_result_from(ResultIndex index, const std::string& what);

}  // namespace aspects
