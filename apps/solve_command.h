// `aspects solve`: run the engine on a model and write its outputs.
#pragma once

#include <stdexcept>
#include <string>

namespace aspects {

struct SolveOptions {
  std::string model_path;  // empty: embedded default (RRRRR)
  double eps = 0.1;
  long prec = 53;
  double tau = 1.01;
  std::string out_dir;
  int threads = 0;  // 0: one per core
  bool progress = false;
  bool no_cert = false;
  bool all_links = false;  // prove every link, not only a spanning forest of the CSNCs
  bool quiet = false;
  std::string bisect = "round-robin";
};

// A bad option value; reported with exit code 2.
class UsageError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

int run_solve(const SolveOptions& opts);

}  // namespace aspects
