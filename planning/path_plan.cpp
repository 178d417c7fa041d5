#include "path_plan.h"

#include <algorithm>
#include <cmath>

#include "path_shortcut.h"
#include "results/pose.h"
#include "results/pose_query.h"
#include "shortest_chain.h"

namespace aspects {

const char* path_outcome_name(PathOutcome o) {
  switch (o) {
    case PathOutcome::Found: return "found";
    case PathOutcome::StartNowhere: return "start_in_no_solution_box";
    case PathOutcome::GoalNowhere: return "goal_in_no_solution_box";
    case PathOutcome::DifferentSigns: return "different_signs";
    case PathOutcome::SameSignsNoPath: return "same_signs_no_certified_path";
    case PathOutcome::ProofFailed: return "proof_failed";
    case PathOutcome::MembershipUnknown: return "membership_unknown";
  }
  return "?";
}

const char* waypoint_kind_name(WaypointKind k) {
  switch (k) {
    case WaypointKind::Start: return "start";
    case WaypointKind::Witness: return "witness";
    case WaypointKind::Corner: return "corner";
    case WaypointKind::Goal: return "goal";
  }
  return "?";
}

const char* path_check_name(PathCheck c) {
  switch (c) {
    case PathCheck::Certified: return "certified";
    case PathCheck::SegmentNotCertified: return "segment_not_certified";
    case PathCheck::NotJoined: return "segments_not_joined";
    case PathCheck::WaypointBox: return "waypoint_box";
    case PathCheck::CommandNotProved: return "command_not_proved";
    case PathCheck::Malformed: return "malformed";
  }
  return "?";
}

// The sign of each factor on a CSNC: constant on an aspect (every factor of det Fx·det Fq
// is nonzero there), so any box whose enclosure has a certain sign gives it; 0 if none.
std::vector<int8_t> csnc_signs(const LoadedResult& r, int32_t k) {
  std::vector<int8_t> s(r.index.factors.size(), 0);
  for (const IndexSolutionBox& b : r.index.solutions) {
    if (b.csnc != k) continue;
    for (size_t f = 0; f < s.size(); ++f)
      if (s[f] == 0) s[f] = b.signs[f];
  }
  return s;
}

namespace {

std::vector<int32_t> csncs_of(const LoadedResult& r, const std::vector<size_t>& boxes) {
  std::vector<int32_t> c;
  for (size_t i : boxes) c.push_back(r.index.solutions[i].csnc);
  std::sort(c.begin(), c.end());
  c.erase(std::unique(c.begin(), c.end()), c.end());
  return c;
}

bool signs_differ(const std::vector<int8_t>& a, const std::vector<int8_t>& b) {
  for (size_t f = 0; f < a.size(); ++f)
    if (a[f] != 0 && b[f] != 0 && a[f] != b[f]) return true;
  return false;
}

// No CSNC holds both poses: can their CSNCs share an aspect?
PathOutcome refuse(const LoadedResult& r, const std::vector<int32_t>& from_csncs,
                   const std::vector<int32_t>& to_csncs) {
  for (int32_t a : from_csncs)
    for (int32_t b : to_csncs)
      if (!signs_differ(csnc_signs(r, a), csnc_signs(r, b))) return PathOutcome::SameSignsNoPath;
  return PathOutcome::DifferentSigns;
}

// Which CSNC joins the poses: Found (proceed) with p.csnc set, or the negative outcome.
PathOutcome choose_csnc(const LoadedResult& r, const std::vector<size_t>& from_boxes,
                        const std::vector<size_t>& to_boxes, int csnc, PathResult& p) {
  p.start_csncs = csncs_of(r, from_boxes);
  p.goal_csncs = csncs_of(r, to_boxes);
  std::set_intersection(p.start_csncs.begin(), p.start_csncs.end(), p.goal_csncs.begin(),
                        p.goal_csncs.end(), std::back_inserter(p.common_csncs));
  std::vector<int32_t> from_k = p.start_csncs;
  if (csnc >= 0) {
    p.csnc = csnc;
    if (!std::binary_search(from_k.begin(), from_k.end(), csnc)) return PathOutcome::StartNowhere;
    from_k = {csnc};
  } else if (!p.common_csncs.empty()) {
    p.csnc = p.common_csncs.front();
  }
  if (from_k.empty()) return PathOutcome::StartNowhere;
  if (p.goal_csncs.empty()) return PathOutcome::GoalNowhere;
  if (!std::binary_search(p.goal_csncs.begin(), p.goal_csncs.end(), p.csnc))
    return refuse(r, from_k, p.goal_csncs);
  return PathOutcome::Found;
}

// Both ends of each chain segment in the box of its first waypoint: sets each waypoint's
// turns (the unwrapped ends of a segment are the points of its box, shifted alike), the
// segments (one box each) and the length.
bool place_segments(const LoadedResult& r, PathResult& p) {
  const size_t d = r.model.pose.size();
  p.waypoints.front().turns.assign(d, 0);
  p.segments.clear();
  for (size_t i = 0; i + 1 < p.waypoints.size(); ++i) {
    Waypoint& a = p.waypoints[i];
    Waypoint& b = p.waypoints[i + 1];
    const IndexSolutionBox& s = r.index.solutions[a.solution];
    std::vector<long> end_turns;
    if (pose_in_box(r.model, a.pose, s.lo.data(), s.hi.data(), &a.box_turns) != Membership::Inside ||
        pose_in_box(r.model, b.pose, s.lo.data(), s.hi.data(), &end_turns) != Membership::Inside) {
      p.failure = "waypoints " + std::to_string(i) + " and " + std::to_string(i + 1) +
                  " are not both in box " + std::to_string(s.id);
      return false;
    }
    b.turns.assign(d, 0);
    b.box_turns = end_turns;  // the goal's box is the last segment's
    PlacedBox placed{a.solution, std::vector<long>(d)};
    double sq = 0;
    for (size_t j = 0; j < d; ++j) {
      placed.shift[j] = a.turns[j] - a.box_turns[j];
      b.turns[j] = placed.shift[j] + end_turns[j];
      const double step = b.pose[j] - a.pose[j] + 2 * M_PI * double(b.turns[j] - a.turns[j]);
      sq += step * step;
    }
    p.segments.push_back(Segment{{placed}, {}});
    p.length += std::sqrt(sq);
  }
  return true;
}

}  // namespace

PathCheck check_path(const LoadedResult& r, CsncLinks& links, const PathResult& p,
                     size_t* segment, SegmentCheck* why) {
  const size_t d = r.model.pose.size();
  if (p.waypoints.size() < 2 || p.segments.size() + 1 != p.waypoints.size())
    return PathCheck::Malformed;
  for (const Waypoint& w : p.waypoints)
    if (w.pose.size() != d || w.turns.size() != d || w.box_turns.size() != d)
      return PathCheck::Malformed;
  for (size_t i = 0; i < p.segments.size(); ++i) {
    const Segment& s = p.segments[i];
    const Waypoint& a = p.waypoints[i];
    const Waypoint& b = p.waypoints[i + 1];
    const SegmentCheck c = check_segment(r, links, {a.pose, a.turns}, {b.pose, b.turns}, s);
    if (c != SegmentCheck::Certified) {
      if (segment) *segment = i;
      if (why) *why = c;
      return PathCheck::SegmentNotCertified;
    }
    if (i > 0 && !(p.segments[i - 1].boxes.back() == s.boxes.front()) &&
        !links.linked(p.segments[i - 1].boxes.back(), s.boxes.front())) {
      if (segment) *segment = i;
      return PathCheck::NotJoined;
    }
  }
  for (size_t i = 0; i < p.waypoints.size(); ++i) {
    const Waypoint& w = p.waypoints[i];
    const PlacedBox& b = i + 1 < p.waypoints.size() ? p.segments[i].boxes.front()
                                                     : p.segments.back().boxes.back();
    if (w.solution != b.solution || w.box != r.index.solutions[b.solution].id)
      return PathCheck::WaypointBox;
    for (size_t j = 0; j < d; ++j)
      if (w.turns[j] - w.box_turns[j] != b.shift[j]) return PathCheck::WaypointBox;
    if (w.command.status != PointCommandStatus::Certified) return PathCheck::CommandNotProved;
  }
  return PathCheck::Certified;
}

PathResult plan_path(const LoadedResult& r, ModelEvaluator& ev, const std::vector<double>& from,
                     const std::vector<double>& to, int csnc, PathShape shape) {
  PathResult p;
  p.straight = pose_distance(from, to, r.pose_periodic);
  const BoxesAtPose at_from = solution_boxes_at(r, from);
  const BoxesAtPose at_to = solution_boxes_at(r, to);
  p.outcome = choose_csnc(r, at_from.inside, at_to.inside, csnc, p);
  if (p.outcome != PathOutcome::Found) {
    // A negative answer needs every membership of both poses decided.
    if (!at_from.unknown.empty() || !at_to.unknown.empty())
      p.outcome = PathOutcome::MembershipUnknown;
    return p;
  }
  CsncLinks links(r, ev, p.csnc);
  Chain chain;
  if (!shortest_chain(r, links, from, to, at_from.inside, at_to.inside, chain)) {
    // The solve's links join the CSNC, and they are among those tried: a link of the
    // index that could not be proved again.
    p.outcome = PathOutcome::ProofFailed;
    p.failure = "no chain of links proved again joins the two poses in CSNC " +
                std::to_string(p.csnc);
    return p;
  }

  // Every command printed is proved here; every link crossed was (CsncLinks).
  const ResultIndex& idx = r.index;
  HsWorkspace ws;
  auto add = [&](WaypointKind kind, const std::vector<double>& pose, size_t box) {
    const IndexSolutionBox& s = idx.solutions[box];
    Waypoint w{kind, pose, box, s.id,
               certified_command(ev, s.lo.data(), s.hi.data(), pose, idx.tau, ws), {}, {}};
    p.waypoints.push_back(std::move(w));
    return p.waypoints.back().command.status == PointCommandStatus::Certified;
  };
  bool ok = add(WaypointKind::Start, from, chain.boxes.front());
  for (size_t i = 0; ok && i < chain.links.size(); ++i)
    ok = add(WaypointKind::Witness, chain.links[i].proof->witness, chain.boxes[i + 1]);
  if (ok) ok = add(WaypointKind::Goal, to, chain.boxes.back());
  if (!ok && p.failure.empty())
    p.failure = "the command of waypoint " + std::to_string(p.waypoints.size() - 1) + " in box " +
                std::to_string(p.waypoints.back().box) + " could not be proved";
  if (ok) ok = place_segments(r, p);
  if (ok) {
    // The chain's own argument, checked as any path's (its links proved again).
    size_t bad = 0;
    const PathCheck c = check_path(r, links, p, &bad);
    if (c != PathCheck::Certified) {
      p.failure = std::string("the chain does not pass the path check (") + path_check_name(c) +
                  " at segment " + std::to_string(bad) + ")";
      ok = false;
    }
  }
  if (!ok) {
    p.outcome = PathOutcome::ProofFailed;
    return p;
  }
  p.chain_waypoints = p.waypoints.size();
  p.chain_length = p.length;
  if (shape == PathShape::Shortcut) {
    PathResult shorter = p;
    if (shortcut_path(r, ev, links, shorter) && check_path(r, links, shorter) == PathCheck::Certified)
      p = std::move(shorter);
  }
  p.outcome = PathOutcome::Found;
  return p;
}

nlohmann::json path_json(const std::vector<double>& from, const std::vector<double>& to,
                         const PathResult& p) {
  nlohmann::json j;
  j["csnc"] = p.csnc >= 0 ? nlohmann::json(p.csnc) : nlohmann::json(nullptr);
  j["outcome"] = path_outcome_name(p.outcome);
  j["from"] = from;
  j["to"] = to;
  j["start_csncs"] = p.start_csncs;
  j["goal_csncs"] = p.goal_csncs;
  j["waypoints"] = nlohmann::json::array();
  for (const Waypoint& w : p.waypoints)
    j["waypoints"].push_back({{"kind", waypoint_kind_name(w.kind)},
                              {"pose", w.pose},
                              {"turns", w.turns},
                              {"command_lo", w.command.lo},
                              {"command_hi", w.command.hi},
                              {"box", w.box}});
  if (p.outcome == PathOutcome::Found) {
    j["length"] = p.length;
    j["straight"] = p.straight;
    j["chain_waypoints"] = p.chain_waypoints;
    j["chain_length"] = p.chain_length;
  }
  if (!p.failure.empty()) j["failure"] = p.failure;
  return j;
}

}  // namespace aspects
