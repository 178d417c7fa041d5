// The options of a solve as given (`aspects solve`'s command line, or aspects.solve's
// arguments), before the plan resolves them (run/solve_plan.h).
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "results/usage_error.h"

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
  bool compress_cert = false;  // aspects.cert.zst instead of aspects.cert
  int cert_format = 2;  // 3: the compact format (certificates/compact_records.h)
  bool all_links = false;  // prove every link, not only a spanning forest of the CSNCs
  bool quiet = false;
  bool mpfi_only = false;  // no double fast path at 53 bits (core/numerics/arithmetic.h)
  std::string bisect = "round-robin";
  // Limits of a long run; negative: none. A stopped run writes a partial
  // result and exits with kExitStopped.
  double time_limit = -1;    // seconds
  long max_boxes = -1;       // boxes processed
  double memory_limit = -1;  // GiB
  // Checkpoints (run/checkpoint.h): the interval in seconds (0: none; not given:
  // kDefaultCheckpointSeconds with --out in a single process, none otherwise), and the
  // directory of a stopped run to continue (its options come from its checkpoint).
  double checkpoint = -1;
  std::string resume_dir;
  std::string program = "aspects";  // as invoked (argv[0]): for the command that resumes
  // The scaling study (run/subtree_stats.h): where to write each part's cost (empty:
  // nowhere), and the depth where the tree is cut into subtrees (-1: the default, 8, or an
  // MPI job's). Neither changes the result.
  std::string subtree_stats;
  int cut_depth = -1;
  std::vector<std::string> given;  // the options given on the command line ("--eps", "MODEL")
  bool was_given(const char* name) const {
    return std::find(given.begin(), given.end(), name) != given.end();
  }
};

// Exit status of a run stopped by a limit or a signal (its outputs are a partial result).
constexpr int kExitStopped = 3;

// The checkpoint interval of a single process with --out when --checkpoint is not given:
// a run stopped after a minute or more, or by a limit or Ctrl-C at any time, can be
// resumed. Not in an MPI job of several processes, where a checkpoint makes every part's
// certificate records pass through rank 0 during the search (README "Distributed runs").
constexpr double kDefaultCheckpointSeconds = 60;

}  // namespace aspects
