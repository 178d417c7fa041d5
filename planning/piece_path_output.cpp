#include "piece_path_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "results/pose.h"
#include "results/usage_error.h"

namespace aspects {

namespace {

// printf into a string: the messages keep their printf form.
template <typename... Args>
std::string text_of(const char* format, Args... args) {
  const int n = std::snprintf(nullptr, 0, format, args...);
  std::string s(size_t(std::max(n, 0)) + 1, '\0');
  std::snprintf(s.data(), s.size(), format, args...);
  s.resize(size_t(std::max(n, 0)));
  return s;
}

// "1 piece", "2 pieces".
std::string counted(long n, const std::string& noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

std::string classes_text(const std::vector<uint32_t>& cs, int p) {
  std::string s;
  for (uint32_t c : cs) s += (s.empty() ? "" : ", ") + class_signs(c, p);
  return s.empty() ? "none" : s;
}

std::string bounds_text(const CountPieces& P) {
  if (P.exact()) return std::to_string(P.lower) + " aspects, exact";
  if (P.upper < 0) return "at least " + std::to_string(P.lower) + " aspects, no upper bound";
  return "between " + std::to_string(P.lower) + " and " + std::to_string(P.upper) + " aspects";
}

const char* outcome_name(PiecePathOutcome o) {
  switch (o) {
    case PiecePathOutcome::Found:
      return "found";
    case PiecePathOutcome::StartNowhere:
      return "start_nowhere";
    case PiecePathOutcome::GoalNowhere:
      return "goal_nowhere";
    case PiecePathOutcome::ClassAbsent:
      return "class_absent";
    case PiecePathOutcome::DifferentClasses:
      return "different_classes";
    case PiecePathOutcome::DifferentAspects:
      return "different_aspects";
    case PiecePathOutcome::NotJoined:
      return "not_joined";
    case PiecePathOutcome::ProofFailed:
      return "proof_failed";
  }
  return "?";
}

const char* kind_name(PieceWaypoint::Kind k) {
  switch (k) {
    case PieceWaypoint::Start:
      return "start";
    case PieceWaypoint::Centre:
      return "centre";
    case PieceWaypoint::Join:
      return "join";
    case PieceWaypoint::Point:
      return "point";
    case PieceWaypoint::Goal:
      return "goal";
  }
  return "?";
}

// A waypoint in the path's unwrapped coordinates: the middle of its enclosure + 2π·turns
// (in doubles: numerical; the enclosure is what is proved).
std::vector<double> unwrapped(const PieceWaypoint& w) {
  std::vector<double> x(w.lo.size());
  for (size_t v = 0; v < x.size(); ++v) x[v] = 0.5 * (w.lo[v] + w.hi[v]) + 2 * M_PI * w.turns[v];
  return x;
}

}  // namespace

// --class: one sign a factor, + or -, in the factors' order.
int64_t parse_class_signs(const std::string& text, int p) {
  if (text.empty()) return -1;
  uint32_t c = 0;
  bool ok = int(text.size()) == p;
  for (int i = 0; ok && i < p; ++i) {
    if (text[i] == '+')
      c |= uint32_t(1) << i;
    else if (text[i] != '-')
      ok = false;
  }
  if (!ok)
    throw UsageError("--class must be " + std::to_string(p) +
                     " signs, each + or - (one per determinant factor, as `aspects count` lists "
                     "them), got '" +
                     text + "'");
  return c;
}

nlohmann::json piece_path_json(const CountDirectory& d, const std::vector<double>& from,
                               const std::vector<double>& to, const PiecePathResult& r) {
  const int p = int(d.pieces.factors.size());
  const Model& m = d.model;
  nlohmann::json j;
  j["count_dir"] = d.directory;
  j["outcome"] = outcome_name(r.outcome);
  j["from"] = from;
  j["to"] = to;
  auto signs = [&](const std::vector<uint32_t>& cs) {
    nlohmann::json a = nlohmann::json::array();
    for (uint32_t c : cs) a.push_back(class_signs(c, p));
    return a;
  };
  j["start_classes"] = signs(r.start_classes);
  j["goal_classes"] = signs(r.goal_classes);
  j["variables"] = nlohmann::json::array();
  for (const auto& v : m.vars) j["variables"].push_back(v.name);
  if (r.outcome != PiecePathOutcome::Found) {
    if (!r.failure.empty()) j["failure"] = r.failure;
    return j;
  }
  j["class"] = class_signs(r.cls, p);
  j["other_classes"] = signs(r.other_classes);
  j["pieces"] = r.pieces;
  j["point_joins"] = r.point_joins;
  j["bridges"] = r.bridges;
  j["waypoints"] = nlohmann::json::array();
  for (const PieceWaypoint& w : r.waypoints)
    j["waypoints"].push_back({{"kind", kind_name(w.kind)},
                              {"box", w.cell},
                              {"config", unwrapped(w)},
                              {"lo", w.lo},
                              {"hi", w.hi},
                              {"turns", w.turns}});
  j["segments"] = nlohmann::json::array();
  for (const PieceSegment& s : r.segments) {
    nlohmann::json u = nlohmann::json::array();
    for (int v : s.u) u.push_back(m.vars[v].name);
    j["segments"].push_back({{"how", s.how == PieceSegment::Star    ? "star"
                                     : s.how == PieceSegment::Graph ? "graph"
                                                                    : "bridge"},
                             {"box", s.cell},
                             {"straight_in", u}});
  }
  return j;
}

std::string piece_path_text(const CountDirectory& d, const std::vector<double>& from,
                            const std::vector<double>& to, const PiecePathResult& r) {
  const int p = int(d.pieces.factors.size());
  const CountPieces& P = d.pieces;
  std::string out;
  out += text_of("robot %s  count %s (%s)  from %s  to %s\n", d.model.name.c_str(),
                 d.directory.c_str(), bounds_text(P).c_str(), format_pose(from).c_str(),
                 format_pose(to).c_str());
  const std::string where = "the start's configurations found are of class " +
                            classes_text(r.start_classes, p) + ", the goal's of class " +
                            classes_text(r.goal_classes, p);
  switch (r.outcome) {
    case PiecePathOutcome::Found: {
      out += "certified singularity-free path through " + counted(r.pieces, "piece") +
             " of class " + class_signs(r.cls, p) + " (one aspect): " +
             counted(long(r.waypoints.size()), "waypoint") + ", " +
             counted(long(r.segments.size()), "segment") + " (" +
             counted(r.point_joins, "join point") + ", " + counted(r.bridges, "bridge") +
             "); each segment is straight in the u-coordinates of its box's chart, not in "
             "pose space\n";
      if (!r.other_classes.empty())
        out += text_of("other classes holding both poses (other working modes): %s (use --class)\n",
                       classes_text(r.other_classes, p).c_str());
      break;
    }
    case PiecePathOutcome::StartNowhere:
      out += text_of(
          "no path: no configuration of the start pose was proved in a piece the count "
          "proved connected (%ld of its boxes with such pieces hold the pose)\n",
          r.start_cells);
      break;
    case PiecePathOutcome::GoalNowhere:
      out += text_of(
          "no path: no configuration of the goal pose was proved in a piece the count "
          "proved connected (%ld of its boxes with such pieces hold the pose)\n",
          r.goal_cells);
      break;
    case PiecePathOutcome::ClassAbsent:
      out += text_of("no path in the class asked for: %s\n", where.c_str());
      break;
    case PiecePathOutcome::DifferentClasses:
      out += text_of(
          "refused: %s; configurations of different classes lie in different aspects, "
          "so no singularity-free path joins them\n",
          where.c_str());
      break;
    case PiecePathOutcome::DifferentAspects:
      out += text_of(
          "refused: the configurations found lie in different aspects: %s, and the "
          "count is exact, so the components of its joined pieces are the aspects, and "
          "none holds a configuration of both poses in one class\n",
          where.c_str());
      break;
    case PiecePathOutcome::NotJoined:
      out += text_of(
          "no certified path: no component of the count's joined pieces holds a "
          "configuration of both poses in one class (%s); the count is not exact, so "
          "they may still lie in one aspect\n",
          where.c_str());
      break;
    case PiecePathOutcome::ProofFailed:
      out += text_of("no certified path: %s\n", r.failure.c_str());
      break;
  }
  return out;
}

}  // namespace aspects
