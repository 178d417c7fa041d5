#include "path_shortcut.h"

#include <cmath>

namespace aspects {

namespace {

UnwrappedPose at(const Waypoint& w) { return {w.pose, w.turns}; }

double segment_length(const Waypoint& a, const Waypoint& b) {
  double sq = 0;
  for (size_t j = 0; j < a.pose.size(); ++j) {
    const double step = b.pose[j] - a.pose[j] + 2 * M_PI * double(b.turns[j] - a.turns[j]);
    sq += step * step;
  }
  return std::sqrt(sq);
}

}  // namespace

bool shortcut_path(const LoadedResult& r, ModelEvaluator& ev, CsncLinks& links, PathResult& p) {
  const std::vector<Waypoint>& w = p.waypoints;
  if (w.size() < 3) return false;
  const size_t last = w.size() - 1;
  std::vector<size_t> kept{0};
  std::vector<Segment> segments;
  PlacedBox box = p.segments.front().boxes.front();
  // Farthest first costs up to W² walks; past this budget only the next waypoint is tried.
  size_t budget = 64 * w.size();
  for (size_t i = 0; i < last;) {
    bool found = false;
    for (size_t j = budget > 0 ? last : i + 1; j > i && !found; --j) {
      if (budget > 0) --budget;
      Segment s;
      if (!find_segment(r, links, at(w[i]), at(w[j]), box, s)) continue;
      if (check_segment(r, links, at(w[i]), at(w[j]), s) != SegmentCheck::Certified) continue;
      segments.push_back(s);
      kept.push_back(j);
      box = s.boxes.back();
      i = j;
      found = true;
    }
    if (!found) return false;
  }
  // Each kept waypoint's command, proved in the first box of its segment (the goal: the
  // last box of the last one).
  const ResultIndex& idx = r.index;
  HsWorkspace ws;
  std::vector<Waypoint> out;
  double length = 0;
  for (size_t k = 0; k < kept.size(); ++k) {
    Waypoint n = w[kept[k]];
    if (k > 0 && k + 1 < kept.size()) n.kind = WaypointKind::Corner;
    const PlacedBox& b = k + 1 < kept.size() ? segments[k].boxes.front() : segments.back().boxes.back();
    const IndexSolutionBox& s = idx.solutions[b.solution];
    n.solution = b.solution;
    n.box = s.id;
    for (size_t j = 0; j < n.turns.size(); ++j) n.box_turns[j] = n.turns[j] - b.shift[j];
    n.command = certified_command(ev, s.lo.data(), s.hi.data(), n.pose, idx.tau, ws);
    if (n.command.status != PointCommandStatus::Certified) return false;
    if (k > 0) length += segment_length(out.back(), n);
    out.push_back(std::move(n));
  }
  p.waypoints = std::move(out);
  p.segments = std::move(segments);
  p.length = length;
  return true;
}

}  // namespace aspects
