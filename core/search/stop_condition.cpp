#include "search/stop_condition.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace aspects {

namespace {
volatile sig_atomic_t g_interrupts = 0;  // SIGINTs caught
volatile sig_atomic_t g_terminated = 0;  // a SIGTERM caught
StopSignalNotes g_notes;                 // set before the handlers are installed

// Async-signal-safe: write(2) of a static string, errno kept for the interrupted code.
void say(const char* text) {
  if (!text) return;
  const int saved = errno;
  ssize_t written = write(STDERR_FILENO, text, std::strlen(text));
  (void)written;  // nothing to do about a failed note
  errno = saved;
}

void on_interrupt(int) {
  const int n = g_interrupts + 1;
  g_interrupts = n;
  if (n == 1) {
    say(g_notes.first_interrupt);
    return;
  }
  struct sigaction dfl {};  // the next one kills, as Ctrl-C usually does
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  sigaction(SIGINT, &dfl, nullptr);
  if (n == 2) say(g_notes.second_interrupt);
}

void on_terminate(int) { g_terminated = 1; }  // one store

int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}
}  // namespace

const char* stop_reason_name(StopReason r) {
  switch (r) {
    case StopReason::TimeLimit: return "time-limit";
    case StopReason::MaxBoxes: return "max-boxes";
    case StopReason::MemoryLimit: return "memory-limit";
    case StopReason::Signal: return "signal";
    default: return "";
  }
}

StopCondition::StopCondition() = default;

void StopCondition::set_time_limit(double seconds) {
  timed_ = true;
  deadline_ = std::chrono::steady_clock::now() +
              std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                  std::chrono::duration<double>(seconds));
}

void StopCondition::set_max_boxes(long boxes) { budget_ = boxes; }

void StopCondition::set_memory_limit(double bytes, double reserve_per_box) {
  memory_limit_ = bytes;
  reserve_per_box_ = reserve_per_box;
}

int StopCondition::interrupts() const {
  return interrupts_.load(std::memory_order_relaxed) + (signals_ ? int(g_interrupts) : 0);
}

StopScope StopCondition::interrupt() {
  interrupts_.fetch_add(1, std::memory_order_relaxed);
  return interrupts() >= 2 ? StopScope::Run : StopScope::Search;
}

void StopCondition::request(StopReason r, StopScope scope) {
  int none = 0;
  reason_.compare_exchange_strong(none, int(r));
  if (scope == StopScope::Run) whole_run_ = true;
}

bool StopCondition::over_memory(long output_boxes) {
  int64_t t = now_ns(), next = next_memory_check_.load(std::memory_order_relaxed);
  if (t < next || !next_memory_check_.compare_exchange_strong(next, t + 5000000)) return false;
  return resident_bytes() + reserve_per_box_ * double(output_boxes) > memory_limit_;
}

StopScope StopCondition::pending(bool search, long output_boxes, StopReason& why) {
  const int n = interrupts();
  why = StopReason::Signal;
  if (n >= 2 || (signals_ && g_terminated)) return StopScope::Run;
  if (search && n >= 1) return StopScope::Search;
  why = StopReason::TimeLimit;
  if (timed_ && std::chrono::steady_clock::now() >= deadline_) return StopScope::Run;
  why = StopReason::MemoryLimit;
  if (memory_limit_ > 0 && over_memory(output_boxes)) return StopScope::Run;
  why = StopReason::None;
  return StopScope::None;
}

bool StopCondition::admit(long output_boxes) {
  if (stopped()) return false;
  StopReason why;
  const StopScope scope = pending(true, output_boxes, why);
  if (scope != StopScope::None) request(why, scope);
  else if (budget_.fetch_sub(1, std::memory_order_relaxed) <= 0)
    request(StopReason::MaxBoxes, StopScope::Search);
  return !stopped();
}

bool StopCondition::search_stopped() {
  if (stopped()) return true;
  StopReason why;
  const StopScope scope = pending(true, 0, why);
  if (scope != StopScope::None) request(why, scope);
  return stopped();
}

bool StopCondition::poll() {
  if (whole_run_) return true;
  StopReason why;
  if (pending(false, 0, why) != StopScope::Run) return false;
  request(why, StopScope::Run);  // after a search-only stop the reason stays its own
  return true;
}

void watch_stop_signals(StopSignalNotes notes) {
  g_notes = notes;
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sa.sa_handler = on_terminate;
  sa.sa_flags = SA_RESETHAND;  // a second SIGTERM kills as usual
  sigaction(SIGTERM, &sa, nullptr);
}

double resident_bytes() {
  FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0;
  long pages = 0, rss = 0;
  int k = std::fscanf(f, "%ld %ld", &pages, &rss);
  std::fclose(f);
  return k == 2 ? double(rss) * double(sysconf(_SC_PAGESIZE)) : 0;
}

double peak_resident_bytes() {
  FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return 0;
  char line[256];
  double kib = 0;
  while (std::fgets(line, sizeof line, f))
    if (std::sscanf(line, "VmHWM: %lf kB", &kib) == 1) break;
  std::fclose(f);
  return kib * 1024;
}

}  // namespace aspects
