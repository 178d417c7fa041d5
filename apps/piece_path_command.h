// `aspects path COUNT_DIR --from POSE --to POSE [--class SIGNS] [--json]`: a certified
// singularity-free path through the pieces of a count (planning/piece_path.h), when DIR was
// written by `aspects count MODEL --out DIR`. Prints one line, or the JSON object.
#pragma once

#include "path_command.h"

namespace aspects {

// Exit code: 0 path found, 1 none (refused or not proved), 2 usage or input error (thrown).
int run_piece_path(const PathOptions& opts);

}  // namespace aspects
