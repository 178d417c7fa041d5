#include "path_command.h"

#include <algorithm>
#include <cmath>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "search/box_store.h"
#include "link.h"
#include "path_plot.h"
#include "pose.h"
#include "query_command.h"
#include "solve_command.h"

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

namespace {

struct EdgeData {
  double weight = 0;
  int32_t link = -1;  // index into ResultIndex::links; -1 for the start and goal edges
};
using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS,
                                    boost::no_property, EdgeData>;

std::vector<int32_t> csncs_of(const LoadedResult& r, const std::vector<size_t>& boxes) {
  std::vector<int32_t> c;
  for (size_t i : boxes) c.push_back(r.index.solutions[i].csnc);
  std::sort(c.begin(), c.end());
  c.erase(std::unique(c.begin(), c.end()), c.end());
  return c;
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

std::vector<double> pose_centre(const LoadedResult& r, size_t i) {
  const IndexSolutionBox& s = r.index.solutions[i];
  std::vector<double> c;
  for (int v : r.model.pose) c.push_back(0.5 * s.lo[v] + 0.5 * s.hi[v]);
  return c;
}

Box to_box(const IndexSolutionBox& s) {
  Box b(s.lo.size());
  for (size_t v = 0; v < s.lo.size(); ++v) b[v].set_hull(s.lo[v], s.hi[v]);
  return b;
}

// Dijkstra from the start to the goal through the certified links of CSNC k; the boxes
// (solution indices) along the shortest path and the link crossed between each two.
bool shortest_boxes(const LoadedResult& r, int32_t k, const std::vector<double>& from,
                    const std::vector<double>& to, const std::vector<size_t>& from_boxes,
                    const std::vector<size_t>& to_boxes, std::vector<size_t>& boxes,
                    std::vector<int32_t>& links) {
  const ResultIndex& idx = r.index;
  std::vector<int32_t> local(idx.solutions.size(), -1);
  std::vector<size_t> global;
  for (size_t i = 0; i < idx.solutions.size(); ++i)
    if (idx.solutions[i].csnc == k) {
      local[i] = int32_t(global.size());
      global.push_back(i);
    }
  const int source = int(global.size()), target = source + 1;
  Graph g(global.size() + 2);
  std::vector<std::vector<double>> centre(global.size());
  for (size_t v = 0; v < global.size(); ++v) centre[v] = pose_centre(r, global[v]);
  for (size_t l = 0; l < idx.links.size(); ++l) {
    const IndexLink& e = idx.links[l];
    if (local[e.a] < 0 || local[e.b] < 0) continue;
    double w = pose_distance(centre[local[e.a]], e.witness, r.pose_periodic) +
               pose_distance(e.witness, centre[local[e.b]], r.pose_periodic);
    boost::add_edge(local[e.a], local[e.b], EdgeData{w, int32_t(l)}, g);
  }
  for (size_t i : from_boxes) {
    if (local[i] < 0) continue;
    double w = pose_distance(from, centre[local[i]], r.pose_periodic);
    boost::add_edge(source, local[i], EdgeData{w, -1}, g);
  }
  for (size_t i : to_boxes) {
    if (local[i] < 0) continue;
    double w = pose_distance(centre[local[i]], to, r.pose_periodic);
    boost::add_edge(local[i], target, EdgeData{w, -1}, g);
  }
  std::vector<Graph::vertex_descriptor> pred(boost::num_vertices(g));
  std::vector<double> dist(boost::num_vertices(g));
  boost::dijkstra_shortest_paths(
      g, Graph::vertex_descriptor(source),
      boost::predecessor_map(pred.data()).distance_map(dist.data())
          .weight_map(boost::get(&EdgeData::weight, g)));
  if (pred[target] == Graph::vertex_descriptor(target)) return false;  // unreachable
  std::vector<Graph::vertex_descriptor> chain;
  for (auto v = pred[target]; v != Graph::vertex_descriptor(source); v = pred[v])
    chain.push_back(v);
  std::reverse(chain.begin(), chain.end());
  boxes.clear();
  links.clear();
  for (size_t i = 0; i < chain.size(); ++i) {
    boxes.push_back(global[chain[i]]);
    if (i + 1 < chain.size()) {
      // Of parallel links (other 2π shifts) between the two boxes, the lightest.
      int32_t best = -1;
      double best_w = 0;
      auto [it, end] = boost::out_edges(chain[i], g);
      for (; it != end; ++it) {
        if (boost::target(*it, g) != chain[i + 1]) continue;
        if (best < 0 || g[*it].weight < best_w) best = g[*it].link, best_w = g[*it].weight;
      }
      links.push_back(best);
    }
  }
  return true;
}

}  // namespace

namespace {

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

// The argument's premise, checked: both ends of each segment lie in the box of its first
// waypoint. Sets each waypoint's turns (the unwrapped ends of a segment are the points of
// its box, shifted alike) and the length of the path as printed.
bool place_segments(const LoadedResult& r, PathResult& p) {
  const size_t d = r.model.pose.size();
  p.waypoints.front().turns.assign(d, 0);
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
    double sq = 0;
    for (size_t j = 0; j < d; ++j) {
      b.turns[j] = a.turns[j] - a.box_turns[j] + end_turns[j];
      const double step = b.pose[j] - a.pose[j] + 2 * M_PI * double(b.turns[j] - a.turns[j]);
      sq += step * step;
    }
    p.length += std::sqrt(sq);
  }
  return true;
}

}  // namespace

PathResult plan_path(const LoadedResult& r, ModelEvaluator& ev, const std::vector<double>& from,
                     const std::vector<double>& to, int csnc) {
  PathResult p;
  const BoxesAtPose at_from = solution_boxes_at(r, from);
  const BoxesAtPose at_to = solution_boxes_at(r, to);
  p.outcome = choose_csnc(r, at_from.inside, at_to.inside, csnc, p);
  if (p.outcome != PathOutcome::Found) {
    // A negative answer needs every membership of both poses decided.
    if (!at_from.unknown.empty() || !at_to.unknown.empty())
      p.outcome = PathOutcome::MembershipUnknown;
    return p;
  }
  std::vector<size_t> boxes;
  std::vector<int32_t> links;
  if (!shortest_boxes(r, p.csnc, from, to, at_from.inside, at_to.inside, boxes, links)) {
    // Cannot happen for a CSNC (a connected component of the links); kept as a refusal.
    p.outcome = PathOutcome::ProofFailed;
    p.failure = "no chain of links joins the two poses in CSNC " + std::to_string(p.csnc);
    return p;
  }

  // Every command printed, and every link crossed, is proved again here.
  const ResultIndex& idx = r.index;
  HsWorkspace ws;
  auto add = [&](WaypointKind kind, const std::vector<double>& pose, size_t box) {
    const IndexSolutionBox& s = idx.solutions[box];
    Waypoint w{kind, pose, box, s.id,
               certified_command(ev, s.lo.data(), s.hi.data(), pose, idx.tau, ws), {}, {}};
    p.waypoints.push_back(std::move(w));
    return p.waypoints.back().command.status == PointCommandStatus::Certified;
  };
  bool ok = add(WaypointKind::Start, from, boxes.front());
  for (size_t i = 0; ok && i < links.size(); ++i) {
    const IndexLink& l = idx.links[links[i]];
    BoxStore pair(int(idx.nv));
    pair.push(to_box(idx.solutions[l.a]));
    pair.push(to_box(idx.solutions[l.b]));
    LinkProof proof;
    if (!certify_link(ev, pair, NeighborPair{0, 1, l.shift_code}, idx.tau, proof, ws)) {
      p.failure = "link between boxes " + std::to_string(idx.solutions[l.a].id) + " and " +
                  std::to_string(idx.solutions[l.b].id) + " could not be proved again";
      ok = false;
      break;
    }
    ok = add(WaypointKind::Witness, proof.witness, boxes[i + 1]);
  }
  if (ok) ok = add(WaypointKind::Goal, to, boxes.back());
  if (ok) ok = place_segments(r, p);
  if (!ok) {
    if (p.failure.empty())
      p.failure = "the command of waypoint " + std::to_string(p.waypoints.size() - 1) +
                  " in box " + std::to_string(p.waypoints.back().box) + " could not be proved";
    p.outcome = PathOutcome::ProofFailed;
    return p;
  }
  p.outcome = PathOutcome::Found;
  return p;
}

namespace {

// The printed pose: pose + 2π·turns, rounded to double.
std::vector<double> unwrapped(const Waypoint& w) {
  std::vector<double> u = w.pose;
  for (size_t j = 0; j < u.size() && j < w.turns.size(); ++j) u[j] += 2 * M_PI * double(w.turns[j]);
  return u;
}

bool any_turn(const Waypoint& w) {
  return std::any_of(w.turns.begin(), w.turns.end(), [](long k) { return k != 0; });
}

const char* kind_name(WaypointKind k) {
  return k == WaypointKind::Start ? "start" : k == WaypointKind::Goal ? "goal" : "witness";
}

std::string csnc_list(const LoadedResult& r, const std::vector<int32_t>& cs) {
  std::string s;
  for (int32_t k : cs) {
    std::string sg;
    for (int8_t x : csnc_signs(r, k)) sg += x > 0 ? '+' : x < 0 ? '-' : '0';
    s += (s.empty() ? "" : ", ") + std::to_string(k) + " (signs " + sg + ")";
  }
  return s.empty() ? "none" : s;
}

void print_text(const LoadedResult& r, const PathOptions& o, const std::vector<double>& from,
                const std::vector<double>& to, const PathResult& p) {
  const Model& m = r.model;
  std::printf("robot %s  eps %g  from %s  to %s\n", m.name.c_str(), r.index.eps,
              format_pose(from).c_str(), format_pose(to).c_str());
  std::string where = "the start lies in CSNC " + csnc_list(r, p.start_csncs) +
                      "; the goal in CSNC " + csnc_list(r, p.goal_csncs);
  switch (p.outcome) {
    case PathOutcome::Found:
      std::printf("certified singularity-free path in CSNC %d: %zu waypoints, length %.6g\n",
                  p.csnc, p.waypoints.size(), p.length);
      for (const Waypoint& w : p.waypoints) {
        std::printf("  %-7s %s  box %u:", kind_name(w.kind), format_pose(unwrapped(w)).c_str(),
                    w.box);
        for (int j = 0; j < m.n(); ++j)
          std::printf(" %s in [%.17g, %.17g]", m.vars[m.command[j]].name.c_str(),
                      w.command.lo[j], w.command.hi[j]);
        std::printf("  width %.3g\n", w.command.width());
      }
      if (any_turn(p.waypoints.back()))
        std::printf("the goal is printed unwrapped: the pose given plus a whole number of turns "
                    "(2*pi) on the periodic coordinates, the same pose of the robot\n");
      std::printf("each segment is straight in the pose space between its printed ends "
                  "(periodic coordinates unwrapped, continuing past +-pi), inside the box of "
                  "its first waypoint shifted by whole turns, where the command is that box's "
                  "continuous nonsingular κ\n");
      if (p.common_csncs.size() > 1 && o.csnc < 0)
        std::printf("other CSNCs holding both poses (other working modes): %s (use --csnc)\n",
                    csnc_list(r, {p.common_csncs.begin() + 1, p.common_csncs.end()}).c_str());
      break;
    case PathOutcome::StartNowhere:
      if (o.csnc >= 0)
        std::printf("no path: the start lies in no solution box of CSNC %d; %s\n", o.csnc,
                    where.c_str());
      else
        std::printf("no path: the start lies in no solution box; %s\n", where.c_str());
      break;
    case PathOutcome::GoalNowhere:
      std::printf("no path: the goal lies in no solution box; %s\n", where.c_str());
      break;
    case PathOutcome::DifferentSigns:
      std::printf("refused: no CSNC holds both poses and their CSNCs have different determinant "
                  "signs, so they lie in different aspects: no singularity-free path joins "
                  "these configurations; %s\n", where.c_str());
      break;
    case PathOutcome::SameSignsNoPath:
      std::printf("no certified path: no CSNC holds both poses; CSNCs with equal determinant "
                  "signs may still belong to one aspect, but no certified path was found at "
                  "eps %g; %s\n", r.index.eps, where.c_str());
      break;
    case PathOutcome::ProofFailed:
      std::printf("no certified path: %s\n", p.failure.c_str());
      break;
    case PathOutcome::MembershipUnknown:
      std::printf("no certified path, and no claim: whether a pose lies in some solution box "
                  "could not be decided (a periodic coordinate too close to a face); %s\n",
                  where.c_str());
      break;
  }
}

}  // namespace

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
    j["waypoints"].push_back({{"kind", kind_name(w.kind)},
                              {"pose", w.pose},
                              {"turns", w.turns},
                              {"command_lo", w.command.lo},
                              {"command_hi", w.command.hi},
                              {"box", w.box}});
  if (p.outcome == PathOutcome::Found) j["length"] = p.length;
  if (!p.failure.empty()) j["failure"] = p.failure;
  return j;
}

int run_path(const PathOptions& opts) {
  LoadedResult r = load_result(opts.result_dir);
  if (const std::string note = certificate_note(r); !note.empty())
    std::cerr << "aspects: note: " << note << '\n';
  std::vector<double> from = parse_pose(opts.from, "--from", r.model);
  std::vector<double> to = parse_pose(opts.to, "--to", r.model);
  if (opts.csnc < -1 || (opts.csnc >= 0 && uint32_t(opts.csnc) >= r.index.csnc_count))
    throw UsageError("--csnc must be between 0 and " + std::to_string(r.index.csnc_count - 1) +
                     " (the result has " + std::to_string(r.index.csnc_count) + " CSNCs), got " +
                     std::to_string(opts.csnc));
  ModelEvaluator ev(r.model);
  PathResult p = plan_path(r, ev, from, to, opts.csnc);
  const nlohmann::json j = path_json(from, to, p);
  if (opts.json)
    std::cout << j.dump() << '\n';
  else
    print_text(r, opts, from, to, p);
  if (!opts.plot.empty() && p.outcome == PathOutcome::Found) write_path_plot(r, j, opts.plot);
  if (!opts.plot.empty() && p.outcome != PathOutcome::Found)
    std::cerr << "aspects: no path, so no figure written to " << opts.plot << '\n';
  return p.outcome == PathOutcome::Found ? 0 : 1;
}

}  // namespace aspects
