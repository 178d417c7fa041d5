// Wall time and the process's peak resident memory at the end of each phase (summary.json's
// `phases`): which phase took the time, which raised the peak.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "search/stop_condition.h"

namespace aspects {

class PhaseClock {
 public:
  using Laps = std::vector<std::pair<std::string, double>>;
  using Listener = std::function<void(const std::string& phase, double seconds)>;
  // `listener`, when set, hears of each phase as it ends.
  explicit PhaseClock(Listener listener = {})
      : start_(std::chrono::steady_clock::now()), last_(start_), listener_(std::move(listener)) {}
  void lap(const char* phase) {
    auto now = std::chrono::steady_clock::now();
    seconds_.emplace_back(phase, std::chrono::duration<double>(now - last_).count());
    peak_mib_.emplace_back(phase, peak_resident_bytes() / (1024.0 * 1024.0));
    last_ = now;
    if (listener_) listener_(phase, seconds_.back().second);
  }
  double total_seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  const Laps& seconds() const { return seconds_; }
  const Laps& peak_mib() const { return peak_mib_; }

 private:
  std::chrono::steady_clock::time_point start_, last_;
  Listener listener_;
  Laps seconds_, peak_mib_;
};

}  // namespace aspects
