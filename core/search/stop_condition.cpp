#include "search/stop_condition.h"

#include <signal.h>
#include <unistd.h>

#include <cstdio>

namespace aspects {

namespace {
volatile sig_atomic_t g_signalled = 0;

void on_stop_signal(int) { g_signalled = 1; }  // async-signal-safe: one store

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

void StopCondition::request(StopReason r) {
  int none = 0;
  reason_.compare_exchange_strong(none, int(r));
}

bool StopCondition::over_memory(long output_boxes) {
  int64_t t = now_ns(), next = next_memory_check_.load(std::memory_order_relaxed);
  if (t < next || !next_memory_check_.compare_exchange_strong(next, t + 5000000)) return false;
  return resident_bytes() + reserve_per_box_ * double(output_boxes) > memory_limit_;
}

bool StopCondition::admit(long output_boxes) {
  if (stopped()) return false;
  if (signals_ && g_signalled) request(StopReason::Signal);
  else if (timed_ && std::chrono::steady_clock::now() >= deadline_) request(StopReason::TimeLimit);
  else if (memory_limit_ > 0 && over_memory(output_boxes)) request(StopReason::MemoryLimit);
  else if (budget_.fetch_sub(1, std::memory_order_relaxed) <= 0) request(StopReason::MaxBoxes);
  return !stopped();
}

bool StopCondition::poll() {
  const StopReason r = reason();
  if (r != StopReason::None && r != StopReason::MaxBoxes) return true;
  StopReason now = StopReason::None;
  if (signals_ && g_signalled) now = StopReason::Signal;
  else if (timed_ && std::chrono::steady_clock::now() >= deadline_) now = StopReason::TimeLimit;
  else if (memory_limit_ > 0 && over_memory(0)) now = StopReason::MemoryLimit;
  if (now == StopReason::None) return false;
  request(now);  // after a max-boxes stop the reason stays max-boxes
  return true;
}

void watch_stop_signals() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;  // the second signal kills as usual
  sigaction(SIGINT, &sa, nullptr);
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
