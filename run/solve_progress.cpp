#include "run/solve_progress.h"

#include <algorithm>
#include <cstdio>

#include "search/stop_condition.h"

namespace aspects {

namespace {
double mib(double bytes) { return bytes / (1024.0 * 1024.0); }

std::string duration(double s) {
  char buf[32];
  if (s < 120) std::snprintf(buf, sizeof buf, "%.0f s", s);
  else if (s < 7200) std::snprintf(buf, sizeof buf, "%.0f min", s / 60);
  else std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
  return buf;
}
}  // namespace

std::string SolveProgress::share_line(double share, double t) {
  share = std::min(1.0, std::max(0.0, share));
  if (last_share_ >= 0 && t > last_t_) {
    double recent = (share - last_share_) / (t - last_t_);
    rate_ = rate_ > 0 ? 0.7 * rate_ + 0.3 * recent : recent;
  }
  last_share_ = share;
  last_t_ = t;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.1f%% of the domain decided", 100 * share);
  std::string line = buf;
  if (rate_ > 0 && share < 1) line += ", about " + duration((1 - share) / rate_) + " left";
  return line;
}

void SolveProgress::tick(const SearchStats& s) {
  auto now = std::chrono::steady_clock::now();
  // A terminal gets one line rewritten in place; a log gets a first line after 1 s (the
  // search has begun: Ctrl-C now keeps what it made), then one every 10 s.
  if (now - last_ < std::chrono::milliseconds(tty_ ? 500 : lines_ == 0 ? 1000 : 10000)) return;
  last_ = now;
  ++lines_;
  double t = std::chrono::duration<double>(now - start_).count();
  std::string share = share_line(s.resumed_share + s.decided.load(), t);
  std::fprintf(stderr,
               "%s[aspects] %ld boxes processed, %ld solution, %ld undecided, %.0f boxes/s, "
               "%.0f MiB, %s%s",
               tty_ ? "\r" : "", long(s.processed), long(s.solutions), long(s.undecided),
               double(s.processed) / std::max(t, 1e-9), mib(resident_bytes()), share.c_str(),
               tty_ ? "   " : "\n");
}

void SolveProgress::phase(const std::string& name, double seconds) {
  std::fprintf(stderr, "%s[aspects] %s: %.1f s, %.0f MiB\n", tty_ ? "\r" : "", name.c_str(),
               seconds, mib(resident_bytes()));
}

void SolveProgress::done(const Model& m, const AspectsResult& r, double resident_mib) {
  std::string stopped;
  if (!r.complete()) {
    char buf[96];
    std::snprintf(buf, sizeof buf, ", stopped by %s with %.1f%% of the domain decided",
                  stop_reason_name(r.stopped_by), 100 * decided_share(m, r));
    stopped = buf;
  }
  std::fprintf(stderr,
               "%s[aspects] done: %ld boxes processed, %d output boxes, %zu certified links, "
               "%.1f s, %.0f MiB%s\n",
               tty_ ? "\r" : "", r.processed, r.boxes.size(), r.certified_links.size(),
               r.seconds, resident_mib, stopped.c_str());
}

double decided_share(const Model& m, const AspectsResult& r) {
  if (r.complete()) return 1;
  Box root = m.initial_box();
  double left = 0;
  const BoxStore& boxes = r.boxes.ends();
  for (int b = 0; b < r.boxes.size(); ++b) {
    if (!r.boxes.unexplored(b)) continue;
    double f = 1;
    for (int v = 0; v < boxes.nv(); ++v) {
      double w = root[v].hi_up() - root[v].lo_down();
      if (w > 0) f *= (boxes.hi(b, v) - boxes.lo(b, v)) / w;
    }
    left += f;
  }
  return std::max(0.0, 1 - left);
}

}  // namespace aspects
