// `aspects count`: the certified number of aspects, or certified bounds on it
// (proofs/counting/exact_count.h). Prints the count line first, then what holds the gap.
#pragma once

#include <string>

namespace aspects {

struct CountOptions {
  std::string model_path;  // empty: the embedded RRRRR
  double eps = 0.5;
  double min_width = 1e-9;
  int rounds = 200;
  double time_limit = 0;
  int threads = 0;
  bool json = false;
  bool progress = false;
  std::string cert;  // --cert FILE: the count's certificate (certificates/FORMAT.md)
  std::string out;   // --out DIR: count.pieces and summary.json (results/count_pieces.h)
};

// Exit status: 0 when the run finished (exact or not: the line says which), 3 when a time
// limit or a signal stopped it (the bounds printed still hold), 2 for a refused model.
int run_count(const CountOptions& options);

}  // namespace aspects
