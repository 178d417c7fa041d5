// The commands of a pose (`aspects query`, Result.query), from the solution boxes that
// contain it, grouped by CSNC (paper 4.1: κ_S in each box S), each enclosure proved at
// the pose (point_command.h). A pose on a face shared by boxes has its command certified in
// each: it is listed once, with every box, when proved one solution (same_command.h), and
// the commands neither proved one nor proved distinct are named. A pose in no solution box
// is classified with the coverage of the result (S ∪ U holds every feasible solution of the domain). Membership in a box
// is decided exactly (pose.h), so "in no box" is a proof, not a failed test.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "results/loaded_result.h"
#include "results/point_command.h"

namespace aspects {

struct QueryAnswer {
  int32_t csnc = -1;
  uint32_t box = 0;        // box id (boxes.csv)
  size_t solution = 0;     // index into ResultIndex::solutions
  PointCommand command;
  // Other solution boxes whose certified command at the pose is proved this one (ids,
  // and their CSNCs): the command is listed once.
  std::vector<uint32_t> same_boxes;
  std::vector<int32_t> same_csncs;
};

enum class QueryOutcome {
  Answered,          // at least one certified command
  NotProved,         // in solution boxes, but no enclosure could be proved
  UndecidedRegion,   // in undecided boxes only: near a singularity, a constraint boundary,
                     // or not resolved at this ε
  OutsideWorkspace,  // in no box: certainly no feasible command in the declared domain
  MembershipUnknown, // no certified command, and whether the pose lies in some box was not
                     // decided (pose.h): no claim
};

struct QueryResult {
  QueryOutcome outcome = QueryOutcome::OutsideWorkspace;
  std::vector<QueryAnswer> answers;  // certified ones, one per solution, by (CSNC, box id)
  // Pairs of answers (their boxes) neither proved one solution nor proved distinct: both
  // listed, and they may be one.
  std::vector<std::pair<uint32_t, uint32_t>> not_proved_distinct;
  std::vector<uint32_t> unproved;    // solution boxes containing the pose, no proof
  std::vector<uint32_t> undecided;   // undecided boxes containing the pose
  size_t unexplored = 0;             // of which cells a stopped run never searched
  std::vector<uint32_t> unknown;     // boxes (solution or undecided) of undecided membership
};

const char* query_outcome_name(QueryOutcome o);

struct BoxesAtPose {
  std::vector<size_t> inside;   // solution boxes whose pose part contains the pose
  std::vector<size_t> unknown;  // those whose membership was not decided
};

// Solution boxes of `r` and the pose (indices into solutions).
BoxesAtPose solution_boxes_at(const LoadedResult& r, const std::vector<double>& pose);

QueryResult query_pose(const LoadedResult& r, ModelEvaluator& ev, const std::vector<double>& pose);

// What `aspects query --json` prints: {"pose", "outcome", "answers": [...], ...}.
nlohmann::json query_json(const std::vector<double>& pose, const QueryResult& q,
                          const LoadedResult& r);

}  // namespace aspects
