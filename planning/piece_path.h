// A certified singularity-free path through the pieces of a count (`aspects path DIR` on a
// count directory, results/count_pieces.h): between two configurations of one sign class
// that the count's joined pieces connect, whatever CSNCs of a solve they lie in.
//
// A piece P = W_s ∩ B proved connected is, in its box's chart (u, w(u)), the graph of w over
// a set S of u's. Proved again here, either the whole graph over the box's U lies in W_s
// (Graph: every segment of U lifts into W_s) or S is star-shaped about a centre v (Star: the
// segment from v to any u of S lies in S). A
// joined adjacency is a point of W_s in both boxes, or a bridge: a chart on the hull of both
// boxes whose graph lies in W_s (every segment of the hull's u lifts into W_s). So a path
// goes: the start A (proved in a piece P_0), straight in P_0's u to its centre (a Star
// piece), straight on to the join point with P_1, ..., to the goal B. Every segment is
// straight in the u-coordinates of its piece's chart (or of the bridge's): the
// configuration follows (u, w(u)), which is not a straight line in pose space unless u is
// the pose. Each segment's ends are proved here (iteration (9) of Hansen–Sengupta at the
// point, the enclosure inside the box, every factor of the class's sign), and so is each
// piece and bridge crossed: nothing of the pieces file is taken on trust but the count's
// bounds and joins behind a refusal "in different aspects".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "counting/factor_gradients.h"
#include "model/model.h"
#include "model/model_eval.h"
#include "results/count_pieces.h"

namespace aspects {

// A count directory opened for `aspects path`: its pieces file and the model parsed again,
// at the recorded precision, with its determinant factors (checked against the recorded
// ones) and their gradients' nodes.
struct CountDirectory {
  CountPieces pieces;
  Model model;
  std::vector<int> factor_nodes;
  std::vector<std::string> factor_origins;  // "det Fx", ..., in the factors' order
  std::string directory;
};

// Throws IndexError (a missing or malformed file, a model that no longer parses or whose
// factors differ from the count's).
CountDirectory load_count_directory(const std::string& dir);

enum class PiecePathOutcome : uint8_t {
  Found,
  StartNowhere,      // no configuration of the start pose was proved in a connected piece
  GoalNowhere,       // nor of the goal pose
  ClassAbsent,       // the class asked for holds no such configuration of a pose
  DifferentClasses,  // proved: the configurations found are of different classes
  DifferentAspects,  // proved (the count is exact): same class, different aspects
  NotJoined,         // same class, not joined through the pieces (the count is not exact)
  ProofFailed,       // a point or bridge of every route failed to be proved again
};

// A configuration proved in a piece: the proved values in its cell's frame, as an
// enclosure (lo, hi per variable, model order), and the whole turns k that place it in the
// path's unwrapped coordinates (the configuration + 2πk).
struct PieceWaypoint {
  enum Kind : uint8_t { Start, Centre, Join, Point, Goal } kind = Start;
  int32_t cell = -1;            // the cell whose piece it was proved in (a join: the next one)
  std::vector<double> lo, hi;
  std::vector<int> turns;       // per variable
};

// The straight segment (in u) from waypoint i to i+1.
struct PieceSegment {
  enum How : uint8_t { Graph, Star, Bridge } how = Graph;
  int32_t cell = -1;            // the piece's cell (Bridge: the first of the two)
  std::vector<int> u;           // the chart's u variables the segment is straight in
};

struct PiecePathResult {
  PiecePathOutcome outcome = PiecePathOutcome::StartNowhere;
  uint32_t cls = 0;
  std::vector<PieceWaypoint> waypoints;
  std::vector<PieceSegment> segments;
  int pieces = 0, point_joins = 0, bridges = 0;
  // The classes of the configurations proved for each pose, and the other classes both
  // poses have configurations of (other working modes).
  std::vector<uint32_t> start_classes, goal_classes, other_classes;
  long start_cells = 0, goal_cells = 0;  // boxes of the cover holding the pose (exact)
  std::string failure;
};

// cls: the class to stay in, or -1 (the lowest class that joins the poses). Poses in pose
// order, as parse_pose returns them.
PiecePathResult plan_piece_path(const CountDirectory& dir, ModelEvaluator& ev,
                                const FactorGradients& fg, const std::vector<double>& from,
                                const std::vector<double>& to, int64_t cls);

// "+-" for a class (factor i: bit i).
std::string class_signs(uint32_t cls, int factors);

}  // namespace aspects
