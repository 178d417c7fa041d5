// When a long run stops early: a time limit, a number of processed boxes, a
// memory limit, or a signal. The search asks before each box; once a reason is set
// it stays set, and every thread leaves the rest of its work unexplored (the cells are
// kept, so coverage and the lower bound stay sound).
//
// A stop reaches the search alone or the whole run (StopScope). A spent max-boxes budget
// and a user's first interrupt (Ctrl-C: SIGINT, or interrupt()) stop the search only: the
// phases after it still run on what was searched, cheap next to the search, so that the
// user gets the links, CSNCs and bound of the boxes made. A second interrupt, SIGTERM, a
// time limit and a memory limit stop the whole run: the phases stop between units of work,
// keeping what they established.
#pragma once

#include <atomic>
#include <chrono>
#include <climits>
#include <cstdint>

namespace aspects {

enum class StopReason : int { None = 0, TimeLimit, MaxBoxes, MemoryLimit, Signal };

// How far a stop reaches: nothing, the search (no more boxes), or the whole run.
enum class StopScope : int { None = 0, Search, Run };

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
  // Counts the signals watch_stop_signals() catches: SIGINT as interrupts, SIGTERM as a
  // stop of the whole run.
  void set_watch_signals(bool on) { signals_ = on; }

  // A user's interrupt (Ctrl-C) not seen as a SIGINT (Python's KeyboardInterrupt): the
  // first stops the search, the second the whole run. Returns the scope it now asks for.
  // The search sees it before its next box; once the search is over, a first interrupt
  // changes nothing (the result stays complete).
  StopScope interrupt();

  // Before processing one more box: false when the search must stop. Counts the box
  // against the max-boxes budget otherwise (exactly, across threads).
  bool admit(long output_boxes);
  // Between units of the search that are not boxes (handing out subtrees): true when the
  // search must stop.
  bool search_stopped();
  // Between units of work of the phases after the search: true when the run must stop
  // (a second interrupt, SIGTERM, the time limit, the resident memory above the limit).
  // A spent max-boxes budget or a first interrupt stopped the search alone: the phases
  // after it still run.
  bool poll();
  // The first reason wins; a later request can still widen the scope to the whole run.
  void request(StopReason r, StopScope scope = StopScope::Run);
  StopReason reason() const { return StopReason(reason_.load(std::memory_order_relaxed)); }
  // The search was stopped (whatever the scope).
  bool stopped() const { return reason() != StopReason::None; }
  // The interrupts so far: this condition's (interrupt()) and, when it watches signals,
  // the SIGINTs caught.
  int interrupts() const;

 private:
  bool over_memory(long output_boxes);
  // The stop the signals, interrupts and limits ask for now (None: go on); `search`: asked
  // by the search, which a first interrupt stops.
  StopScope pending(bool search, long output_boxes, StopReason& why);

  std::atomic<int> reason_{0};
  std::atomic<bool> whole_run_{false};
  std::atomic<int> interrupts_{0};
  std::atomic<long> budget_{LONG_MAX};
  bool timed_ = false, signals_ = false;
  std::chrono::steady_clock::time_point deadline_;
  double memory_limit_ = 0, reserve_per_box_ = 0;
  // /proc/self/statm is read at most every few milliseconds (one thread at a time).
  std::atomic<int64_t> next_memory_check_{0};
};

// What the signal handlers print on stderr (write(2), from the handler), each null for
// nothing: on the first SIGINT, and on the second. Static strings.
struct StopSignalNotes {
  const char* first_interrupt = nullptr;
  const char* second_interrupt = nullptr;
};

// Installs handlers for SIGINT and SIGTERM, counted by every StopCondition watching
// signals. SIGINT: the first stops the search, the second the whole run, and the third
// gets the default action (so Ctrl-C still kills a run that does not stop). SIGTERM stops
// the whole run; a second one gets the default action.
void watch_stop_signals(StopSignalNotes notes = {});
// Resident memory of this process, in bytes (0 when /proc is unavailable).
double resident_bytes();
// The largest resident memory of this process so far (VmHWM), in bytes (0 when /proc is
// unavailable).
double peak_resident_bytes();

}  // namespace aspects
