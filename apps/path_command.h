// `aspects path RESULT_DIR --from POSE --to POSE [--csnc K] [--json] [--out FILE]
// [--plot FILE]`: plans a certified singularity-free motion between two poses inside one
// CSNC (planning/path_plan.h, where the certification argument is) and prints a one-line
// summary, or the JSON object; `--out` writes the waypoints (planning/path_output.h).
// On a count directory (`aspects count --out`) it runs piece_path_command.h instead.
#pragma once

#include <string>

#include "path_plan.h"

namespace aspects {

struct PathOptions {
  std::string result_dir;
  std::string from, to;
  int csnc = -1;  // -1: any CSNC holding both poses
  std::string cls;   // --class SIGNS (a count directory only), empty: any class
  bool json = false;
  std::string out;   // CSV or JSON file of the waypoints, empty: none
  std::string plot;  // PNG file, empty: none
};

// Exit code: 0 path found, 1 none, 2 usage or input error (thrown).
int run_path(const PathOptions& opts);

}  // namespace aspects
