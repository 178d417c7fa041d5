// A certified singularity-free motion between two poses inside one CSNC (paper 4.1, 4.3),
// as `aspects path` and Python's Result.path plan it.
//
// Planning. A* finds the shortest chain of boxes of the CSNC joined by links proved on
// demand (shortest_chain.h; any neighbouring boxes, not only the links the solve kept).
// Its waypoints are the start, each link's witness x̂ and the goal, each two consecutive
// ones in one box. The shortcut then keeps as few of them as it can: from a waypoint, the
// farthest one that a straight segment reaches through a chain of linked boxes
// (straight_segment.h), checked there, replaces the waypoints between.
//
// Certification argument. On a solution box S = ([x], [q]), P1 makes κ_S(x) the unique
// q ∈ [q] with f(x, q) = 0 and P2 (Fx, Fq nonsingular on the box, implicit function
// theorem) makes κ_S continuous, indeed C¹, and every configuration (x, κ_S(x))
// nonsingular; every additional constraint holds on the whole box. Each segment lies in a
// chain of linked boxes of the CSNC (straight_segment.h says why κ joins across each
// link); consecutive segments meet at a waypoint in the last box of one and the first of
// the next, the same box or linked ones. check_path re-checks all of it (every link proved
// again, here, with certify_link) and plan_path returns no path it did not pass. Each
// waypoint's command enclosure is proved at that point (point_command.h) in the first box
// of the segment after it (the goal: in the last segment's last box). Waypoints are
// unwrapped (pose + 2π·turns on periodic coordinates): consecutive ones are the two ends
// of the straight segment as it runs, a segment across the ±π seam included.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "results/loaded_result.h"
#include "results/point_command.h"
#include "straight_segment.h"

namespace aspects {

// Corner: a waypoint the shortcut kept (a link's witness of the chain it shortened).
enum class WaypointKind { Start, Witness, Corner, Goal };

struct Waypoint {
  WaypointKind kind = WaypointKind::Start;
  std::vector<double> pose;
  size_t solution = 0;      // the first box of the segment that follows (the goal: its own box)
  uint32_t box = 0;         // its id
  PointCommand command;     // κ of that box at the pose
  std::vector<long> turns;      // pose order: printed as pose + 2π·turns (unwrapped)
  std::vector<long> box_turns;  // pose + 2π·box_turns lies in the box
};

enum class PathOutcome {
  Found,             // every waypoint and link proved
  StartNowhere,      // the start lies in no solution box (of CSNC K when given)
  GoalNowhere,       // the goal lies in no solution box
  DifferentSigns,    // no common CSNC; every pair of CSNCs has different determinant signs:
                     // the two configurations lie in different aspects
  SameSignsNoPath,   // no common CSNC, but some pair has equal signs: maybe one aspect,
                     // no certified path at this ε
  ProofFailed,       // a waypoint's command or a link could not be proved again
  MembershipUnknown, // no path found, and whether a pose lies in some box was not decided
                     // (pose.h): no claim
};

// Shortcut: as few waypoints as the shortcut finds; Chain: the start, every link's witness
// of the shortest chain, the goal (each segment in one box).
enum class PathShape { Shortcut, Chain };

struct PathResult {
  PathOutcome outcome = PathOutcome::StartNowhere;
  int32_t csnc = -1;
  std::vector<Waypoint> waypoints;
  std::vector<Segment> segments;                 // waypoints.size() − 1, when Found
  std::vector<int32_t> start_csncs, goal_csncs;  // CSNCs whose boxes hold each pose
  std::vector<int32_t> common_csncs;             // both (the path uses the first, or K)
  std::string failure;                           // what could not be proved
  double length = 0;                             // sum of the segment lengths (unwrapped)
  double straight = 0;  // the distance between the poses (periodic ones the short way round)
  size_t chain_waypoints = 0;  // before the shortcut
  double chain_length = 0;
};

const char* path_outcome_name(PathOutcome o);
// The sign of each determinant factor on CSNC k (0: no box decides it).
std::vector<int8_t> csnc_signs(const LoadedResult& r, int32_t k);
const char* waypoint_kind_name(WaypointKind k);

// `csnc` = -1: the smallest-numbered (largest) CSNC holding both poses.
PathResult plan_path(const LoadedResult& r, ModelEvaluator& ev, const std::vector<double>& from,
                     const std::vector<double>& to, int csnc,
                     PathShape shape = PathShape::Shortcut);

enum class PathCheck {
  Certified,
  SegmentNotCertified,  // check_segment refused a segment
  NotJoined,            // consecutive segments end and start in boxes that are not linked
  WaypointBox,          // a waypoint's box is not its segment's (or its turns disagree)
  CommandNotProved,     // a waypoint's command enclosure is not certified
  Malformed,
};

const char* path_check_name(PathCheck c);

// The argument above, checked on a found path; `segment` (if given) gets the index of the
// first segment refused and `why` check_segment's answer.
PathCheck check_path(const LoadedResult& r, CsncLinks& links, const PathResult& p,
                     size_t* segment = nullptr, SegmentCheck* why = nullptr);

// What `aspects path --json` prints: {"csnc", "outcome", "waypoints": [...], "length",
// "straight", "chain_waypoints", "chain_length", ...}.
nlohmann::json path_json(const std::vector<double>& from, const std::vector<double>& to,
                         const PathResult& p);

}  // namespace aspects
