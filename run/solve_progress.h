// Progress of `aspects solve` on stderr (a terminal, or --progress): boxes, rate, memory,
// the share of the initial domain's volume already decided, and an estimate of the time
// left. Display only: nothing here is a claim.
#pragma once

#include <chrono>
#include <string>

#include "generalized_aspects.h"
#include "model/model.h"
#include "search/branch_and_prune.h"

namespace aspects {

class SolveProgress {
 public:
  explicit SolveProgress(bool tty) : tty_(tty) {}
  // Called from the search (any thread, one at a time): prints a line now and then.
  void tick(const SearchStats& s);
  // Called as each phase ends (the phases after the search run minutes on large results).
  void phase(const std::string& name, double seconds);
  // The last line, after the search; a stopped run also says how much it decided.
  void done(const Model& m, const AspectsResult& r, double resident_mib);

  // "37.5% of the domain decided, about 2 min left": the time left is the volume left at
  // the recent pace (an average over the last lines: the first cells, far from any
  // solution, are refuted far faster than the last ones).
  std::string share_line(double share, double seconds);

 private:
  bool tty_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_ = start_;
  double last_t_ = 0, last_share_ = -1, rate_ = 0;  // rate: share per second, smoothed
  long lines_ = 0;  // progress lines printed
};

// The share of the initial domain's volume outside the unexplored boxes of r (1 for a
// complete run); variables of zero width count as a factor 1.
double decided_share(const Model& m, const AspectsResult& r);

}  // namespace aspects
