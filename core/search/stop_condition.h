// When a long run stops early: a time limit, a number of processed boxes, a
// memory limit, or SIGINT/SIGTERM. The search asks before each box; once a reason is set
// it stays set, and every thread leaves the rest of its work unexplored (the cells are
// kept, so coverage and the lower bound stay sound).
#pragma once

#include <atomic>
#include <chrono>
#include <climits>
#include <cstdint>

namespace aspects {

enum class StopReason : int { None = 0, TimeLimit, MaxBoxes, MemoryLimit, Signal };

// "time-limit", "max-boxes", "memory-limit", "signal" (summary.json's stopped_by); "" for None.
const char* stop_reason_name(StopReason r);

class StopCondition {
 public:
  StopCondition();
  void set_time_limit(double seconds);  // from now
  void set_max_boxes(long boxes);       // boxes processed in this run
  // Stops when the resident memory plus `reserve_per_box` bytes per output box (what the
  // phases after the search and the writing of the outputs still need) would pass `bytes`.
  void set_memory_limit(double bytes, double reserve_per_box);
  // Requests a stop on SIGINT or SIGTERM (see watch_stop_signals()).
  void set_watch_signals(bool on) { signals_ = on; }

  // Before processing one more box: false when the search must stop. Counts the box
  // against the max-boxes budget otherwise (exactly, across threads).
  bool admit(long output_boxes);
  // Between units of work of the phases after the search: true when the run must stop
  // (a signal, the time limit, the resident memory above the limit). The max-boxes budget
  // counts the search's boxes only: once spent, the phases after the search still run.
  bool poll();
  void request(StopReason r);  // the first reason wins
  StopReason reason() const { return StopReason(reason_.load(std::memory_order_relaxed)); }
  bool stopped() const { return reason() != StopReason::None; }

 private:
  bool over_memory(long output_boxes);

  std::atomic<int> reason_{0};
  std::atomic<long> budget_{LONG_MAX};
  bool timed_ = false, signals_ = false;
  std::chrono::steady_clock::time_point deadline_;
  double memory_limit_ = 0, reserve_per_box_ = 0;
  // /proc/self/statm is read at most every few milliseconds (one thread at a time).
  std::atomic<int64_t> next_memory_check_{0};
};

// Installs handlers for SIGINT and SIGTERM that make every StopCondition watching signals
// stop; a second signal gets the default action (so a second Ctrl-C still kills).
void watch_stop_signals();
// Resident memory of this process, in bytes (0 when /proc is unavailable).
double resident_bytes();
// The largest resident memory of this process so far (VmHWM), in bytes (0 when /proc is
// unavailable).
double peak_resident_bytes();

}  // namespace aspects
