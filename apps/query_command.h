// `aspects query RESULT_DIR --pose X`: the commands of a pose, from the solution boxes that
// contain it (results/pose_query.h, where what each outcome claims is said), printed as
// text or as one JSON object.
#pragma once

#include <string>

namespace aspects {

struct QueryOptions {
  std::string result_dir;
  std::string pose;
  bool json = false;
};

// Exit code: 0 answered, 1 no certified command, 2 usage or input error (thrown).
int run_query(const QueryOptions& opts);

}  // namespace aspects
