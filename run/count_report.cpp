#include "run/count_report.h"

#include <sstream>

namespace aspects {

namespace {

std::string class_text(uint32_t cls, int p) {
  std::string s;
  for (int i = 0; i < p; ++i) s += (cls >> i) & 1 ? '+' : '-';
  return s;
}

std::string box_text(const OpenPlace& o, const Model& m) {
  std::ostringstream out;
  out.precision(6);
  for (size_t v = 0; v < o.lo.size(); ++v)
    out << (v ? ", " : "") << m.vars[v].name << " in [" << o.lo[v] << ", " << o.hi[v] << "]";
  return out.str();
}

// A factor's text is its expression followed by " (origin)". A long expression (3-RRR*'s det
// Fx has over 1,000 characters) would bury the report, so only its origin is printed;
// `--json` keeps the whole text.
std::string factor_label(const std::string& text, const std::string& origin) {
  constexpr size_t kLongest = 80;
  const size_t suffix = origin.size() + 3;  // " (" origin ")"
  if (text.size() <= kLongest || text.size() < suffix) return text;
  return origin + " [" + std::to_string(text.size() - suffix) + " characters; --json gives it]";
}

// Where a region lies: the hull of its boxes' pose parts.
std::string pose_hull_text(const CountRegion& r, const Model& m) {
  std::ostringstream out;
  out.precision(4);
  for (size_t i = 0; i < m.pose.size(); ++i) {
    const int v = m.pose[i];
    out << (i ? ", " : "") << m.vars[v].name << " in [" << r.lo[v] << ", " << r.hi[v] << "]";
  }
  return out.str();
}

std::string aspects_text(int k) { return std::to_string(k) + (k == 1 ? " aspect" : " aspects"); }

// The lower bound's regions, largest first: each is one aspect when the count is exact, and
// holds at least one otherwise.
void print_regions(std::ostream& out, const Model& m, const CountResult& r) {
  constexpr size_t kShown = 30;
  if (r.regions.empty()) return;
  const int p = int(r.factor_text.size());
  out << (r.bounds.exact() ? "the aspects" : "the regions of the lower bound (each holds at least one aspect)")
      << ", largest first: class, boxes holding it, the hull and the volume of their poses\n";
  for (size_t i = 0; i < r.regions.size() && i < kShown; ++i) {
    const CountRegion& x = r.regions[i];
    out << "  " << i + 1 << ". " << class_text(x.cls, p) << "  " << x.boxes
        << (x.boxes == 1 ? " box" : " boxes") << "  " << pose_hull_text(x, m) << "  volume "
        << x.pose_volume << '\n';
  }
  if (r.regions.size() > kShown)
    out << "  ... and " << r.regions.size() - kShown << " more (--json lists them all)\n";
}

}  // namespace

std::string count_line(const CountBounds& b) {
  if (b.exact()) return aspects_text(b.lower) + " (certified: lower = upper)";
  if (b.upper >= 0)
    return "between " + std::to_string(b.lower) + " and " + aspects_text(b.upper) + " (certified)";
  return "at least " + aspects_text(b.lower) + " (certified); no upper bound: " +
         std::to_string(b.open_pieces) + " piece(s) not proved connected";
}

nlohmann::json count_json(const Model& m, const CountResult& r, double eps) {
  const CountBounds& b = r.bounds;
  const int p = int(r.factor_text.size());
  nlohmann::json j;
  j["robot"] = m.name;
  j["lower_bound"] = b.lower;
  j["upper_bound"] = b.upper < 0 ? nlohmann::json(nullptr) : nlohmann::json(b.upper);
  j["exact"] = b.exact();
  j["stop"] = count_stop_name(r.stop);
  j["open_pieces"] = b.open_pieces;
  j["open_adjacencies"] = b.open_adjacencies;
  j["open_pieces_by_reason"] = {{"no_chart", r.open_by_reason[int(OpenReason::NoChart)]},
                                {"no_point", r.open_by_reason[int(OpenReason::NoPoint)]},
                                {"not_star", r.open_by_reason[int(OpenReason::NotStar)]},
                                {"not_reached", r.open_by_reason[int(OpenReason::NotReached)]},
                                {"constraint_boundary",
                                 r.open_by_reason[int(OpenReason::ConstraintBoundary)]}};
  j["first_cover"] = {{"eps", eps}, {"boxes", r.first_cover_boxes},
                      {"separated_lower_bound", r.separation_bound}};
  j["boxes"] = r.cells;
  j["pieces"] = r.pieces;
  j["adjacencies"] = r.adjacencies;
  j["bisections"] = r.bisections;
  j["rounds"] = r.rounds;
  j["seconds"] = r.seconds;
  j["factors"] = r.factor_text;
  nlohmann::json open = nlohmann::json::array();
  for (const OpenPlace& pl : r.open)
    open.push_back({{"reason", open_reason_name(pl.reason)}, {"class", class_text(pl.cls, p)},
                    {"lo", pl.lo}, {"hi", pl.hi}});
  j["open"] = open;
  nlohmann::json regions = nlohmann::json::array();
  for (const CountRegion& x : r.regions)
    regions.push_back({{"class", class_text(x.cls, p)}, {"boxes", x.boxes},
                       {"connected_pieces", x.connected}, {"lo", x.lo}, {"hi", x.hi},
                       {"pose_volume", x.pose_volume}});
  j["regions"] = regions;
  return j;
}

void print_count_details(std::ostream& out, const Model& m, const CountResult& r, double eps) {
  const CountBounds& b = r.bounds;
  const int p = int(r.factor_text.size());
  out << "robot " << m.name << "  first cover eps " << eps << " (" << r.first_cover_boxes
      << " boxes, separated lower bound " << r.separation_bound << "), then " << r.bisections
      << " bisections where a bound could move\n";
  out << "boxes: " << r.cells << ", pieces: " << r.pieces << ", adjacencies: " << r.adjacencies
      << ", rounds: " << r.rounds << ", " << r.seconds << " s\n";
  out << "sign classes over:";
  for (size_t i = 0; i < r.factor_text.size(); ++i)
    out << "  " << factor_label(r.factor_text[i], r.factor_origin[i]);
  out << '\n';
  print_regions(out, m, r);
  if (b.exact()) return;
  out << "the gap is held by " << b.open_pieces << " piece(s) not proved connected ("
      << r.open_by_reason[int(OpenReason::NoChart)] << " with no chart, "
      << r.open_by_reason[int(OpenReason::NoPoint)] << " with no certified point, "
      << r.open_by_reason[int(OpenReason::NotStar)] << " whose star test failed, "
      << r.open_by_reason[int(OpenReason::NotReached)] << " not decided before the stop"
      << (r.open_by_reason[int(OpenReason::ConstraintBoundary)]
              ? ", " + std::to_string(r.open_by_reason[int(OpenReason::ConstraintBoundary)]) +
                    " on a constraint boundary"
              : std::string())
      << ") and "
      << b.open_adjacencies << " undecided adjacency(ies) between components; "
      << "the refinement ended: " << count_stop_name(r.stop) << '\n';
  for (const OpenPlace& pl : r.open)
    out << "  class " << class_text(pl.cls, p) << ": " << open_reason_name(pl.reason) << ", at "
        << box_text(pl, m) << '\n';
}

}  // namespace aspects
