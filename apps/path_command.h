// `aspects path RESULT_DIR --from POSE --to POSE [--csnc K]`: a certified singularity-free
// motion between two poses inside one CSNC, through certified links (paper 4.1, 4.3).
//
// Certification argument. The waypoints are the start, the witness point x̂ of each link
// crossed, and the goal; every two consecutive waypoints lie in the pose part [x] of one
// common solution box S (modulo 2π on periodic pose coordinates), and the motion between
// them is the straight segment, inside [x] because a box is convex. On [x], P1 makes
// κ_S(x) the unique q ∈ [q] with f(x, q) = 0 and P2 (Fx, Fq nonsingular on the box, implicit
// function theorem) makes κ_S continuous, indeed C¹, and the configurations (x, κ_S(x))
// nonsingular; every additional constraint holds on the whole box. At a witness x̂ that
// joins S and S' (P3, proved again here with certify_link), one q* ∈ [q] ∩ [q'] (modulo 2π)
// solves f(x̂, q*) = 0, so uniqueness in each box gives κ_S(x̂) = q* = κ_S'(x̂): the pieces
// join into one continuous motion that crosses no singularity. Each waypoint's command
// enclosure is proved at that point (point_command.h) in the box of the segment after it.
// Waypoints are printed unwrapped (pose + 2π·turns on periodic coordinates): consecutive
// printed poses are the two ends of the straight segment, as they lie in its box (shifted
// by a whole number of turns), so a segment across the ±π seam is printed as it runs.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "loaded_result.h"
#include "point_command.h"

namespace aspects {

struct PathOptions {
  std::string result_dir;
  std::string from, to;
  int csnc = -1;  // -1: any CSNC holding both poses
  bool json = false;
  std::string plot;  // PNG file, empty: none
};

enum class WaypointKind { Start, Witness, Goal };

struct Waypoint {
  WaypointKind kind = WaypointKind::Start;
  std::vector<double> pose;
  size_t solution = 0;      // the box of the segment that follows (the goal: its own box)
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

struct PathResult {
  PathOutcome outcome = PathOutcome::StartNowhere;
  int32_t csnc = -1;
  std::vector<Waypoint> waypoints;
  std::vector<int32_t> start_csncs, goal_csncs;  // CSNCs whose boxes hold each pose
  std::vector<int32_t> common_csncs;             // both (the path uses the first, or K)
  std::string failure;                           // what could not be proved
  double length = 0;                             // sum of the segment lengths
};

const char* path_outcome_name(PathOutcome o);

// `csnc` = -1: the smallest-numbered (largest) CSNC holding both poses.
PathResult plan_path(const LoadedResult& r, ModelEvaluator& ev, const std::vector<double>& from,
                     const std::vector<double>& to, int csnc);

// What `aspects path --json` prints: {"csnc", "outcome", "waypoints": [...], ...}.
nlohmann::json path_json(const std::vector<double>& from, const std::vector<double>& to,
                         const PathResult& p);

// Exit code: 0 path found, 1 none, 2 usage or input error (thrown).
int run_path(const PathOptions& opts);

}  // namespace aspects
