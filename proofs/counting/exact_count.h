// Counting the aspects exactly (certificates/FORMAT.md, "Counting"): a cover of the
// solution set by boxes (a solve's output boxes, then refined where a decision can move a
// bound), the pieces W_s ∩ B of each box and class decided as empty / connected / nonempty
// / undecided, the adjacencies between pieces of touching boxes as joined / refuted /
// undecided, and the two bounds of core/aspects/count_graph.h. Lower = upper is the count.
//
// What is refined: boxes holding a piece not proved connected (nor empty), and both boxes
// of an undecided adjacency between two components of H that G joins. Nothing else: no
// uniform ε. A box narrower than the least width (relative to the domain) is not bisected;
// what it leaves open is reported, with the place and the test that failed.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "aspects/count_graph.h"
#include "model/model.h"
#include "search/stop_condition.h"

namespace aspects {

// What proves each decision of a count, for its certificate (certificates/FORMAT.md,
// "Count certificates"; written by certificates/count_certificate.h). Boxes are lo/hi
// pairs of doubles in model order. Cells 0..first_cover-1 are the first cover's output
// boxes; every other cell is a half of a bisected cell.
struct CountCellRecord {
  enum Fit : uint8_t {
    NoFit,       // the box is its origin (no chart, a solution box, or not reached)
    Charted,     // a chart on the origin box made it `box`
    Void,        // a chart showed no solution in the origin box
    NoSolution,  // Hansen–Sengupta on the origin box showed no solution in it
  } fit = NoFit;
  std::vector<double> origin, box;  // as created (a contracted half), and at the end
  std::vector<int> w;               // the chart's w (Charted, Void)
  std::vector<double> w_tilde;      // its iterate W̃ (n lo/hi pairs): uniqueness there
  int split_var = -1;               // bisected: at split_at in split_var; halves' ids or -1
  double split_at = 0;
  int32_t child[2] = {-1, -1};
  bool alive = true;
  // The pieces of an alive cell, with what shows each nonempty one (a u-point of W_s).
  // Constraint: a constraint is False on the current box (no feasible point in it).
  enum EmptyBy : uint8_t { NotEmpty, Signs, NoPoint, Paving, OtherClass, Constraint };
  // Connected: the whole graph over U (a solution box, or a chart whose range lies in the
  // box with every factor of one sign), or star-shaped about its point.
  enum ConnectedBy : uint8_t { NotConnected, Graph, Star };
  struct Piece {
    uint32_t cls;
    PieceState state;
    EmptyBy empty_by = NotEmpty;
    ConnectedBy connected_by = NotConnected;
    std::vector<int> point_w;         // a point of W_s in the box: its chart's w,
    std::vector<double> point_u;      // the u-point (n, the chart's u in model order)
    std::vector<double> point_hint;   // and an enclosure of w there (n lo/hi pairs)
  };
  std::vector<Piece> pieces;
};

struct CountRecords {
  long first_cover = 0;
  std::vector<CountCellRecord> cells;
  struct Refuted {
    int32_t a, b;
    uint32_t cls;
  };
  std::vector<Refuted> refuted;  // adjacencies refuted, alive cells only
  // Adjacencies joined, alive cells only: a point of W_s in a ∩ (b + 2πk) (w, u, hint as a
  // piece's point), or a bridge: a chart (w, its iterate W̃) on the hull of a and b + 2πk.
  struct Joined {
    int32_t a, b;
    uint32_t cls;
    std::vector<int> shift;  // k per variable
    bool bridge = false;
    std::vector<int> w;
    std::vector<double> u, hint;  // the point (bridge: empty)
    std::vector<double> w_tilde;  // the bridge's W̃ (n lo/hi pairs)
  };
  std::vector<Joined> joined;
};

struct AspectsResult;
class CertificateSink;

struct CountConfig {
  double eps = 0.5;          // ε of the first cover (a uniform solve); refinement is adaptive
  double min_width = 1e-9;   // relative to the domain: narrower boxes are not bisected
  int max_rounds = 200;
  int threads = 1;           // the first cover's search
  StopCondition* stop = nullptr;
  // Told after each round (stderr progress), with the open pieces by OpenReason.
  void (*progress)(int round, const CountBounds&, long cells, const long* open_by_reason,
                   void* data) = nullptr;
  void* progress_data = nullptr;
  // The certificate: the first cover's records go to `certificate` while it is solved, and
  // `first_cover_done` is told the solve's result (to finish them); the count's decisions
  // come back in CountResult::records.
  CertificateSink* certificate = nullptr;
  void (*first_cover_done)(const AspectsResult&, void* data) = nullptr;
  void* first_cover_data = nullptr;
  // Fill CountResult::records without a certificate (`aspects count --out`: the pieces,
  // centres and joins that `aspects path` plans through).
  bool keep_records = false;
};

// Why a piece is not proved connected.
enum class OpenReason : uint8_t {
  NoChart,     // neither the pose nor the command chart could be proved on the box
  NoPoint,     // a chart holds, but no certified point of the class was found in the box
  NotStar,     // the star-shaped test failed about the point found
  Adjacency,   // an adjacency between two components of H, neither joined nor refuted
  NotReached,  // the refinement stopped before deciding the box
  ConstraintBoundary,  // an `or` of two constraint atoms or more is Unknown on the box
};
constexpr int kOpenReasons = 6;
const char* open_reason_name(OpenReason r);

// A place that holds the gap between the bounds.
struct OpenPlace {
  OpenReason reason;
  uint32_t cls;                 // sign class (bit i: factor i positive)
  std::vector<double> lo, hi;   // the box (model order)
};

enum class CountStop : uint8_t {
  Exact,      // lower = upper
  MinWidth,   // every open place is narrower than the least width
  Rounds,     // the round budget ran out
  Stopped,    // the stop condition (time limit, signal)
};
const char* count_stop_name(CountStop s);

// A component of G (every adjacency not refuted) that holds a piece proved nonempty: each
// holds at least one aspect of its own, exactly one when the count is exact. Its pieces'
// boxes give where it lies (the hull of their pose parts) and an outer measure of its size.
struct CountRegion {
  uint32_t cls = 0;             // its sign class (bit i: factor i positive)
  long boxes = 0;               // boxes holding one of its pieces (not empty)
  long connected = 0;           // of which, pieces proved connected
  std::vector<double> lo, hi;   // hull of those boxes (model order)
  double pose_volume = 0;       // sum of their pose parts' volumes (≥ the region's)
};

struct CountResult {
  CountBounds bounds;
  CountStop stop = CountStop::Exact;
  int separation_bound = 0;     // the first cover's separated lower bound (Section 4.4.2)
  int rounds = 0;
  long first_cover_boxes = 0, cells = 0, pieces = 0, adjacencies = 0;
  long bisections = 0, star_boxes = 0;
  std::vector<OpenPlace> open;  // at most a few, the first found
  long open_by_reason[kOpenReasons] = {};  // open pieces (and adjacencies) by OpenReason
  std::vector<std::string> factor_text;    // "expression (origin)", as solve prints them
  std::vector<std::string> factor_origin;  // "det Fx", "diagonal Fq, entry (1,1)", ...
  std::vector<CountRegion> regions;  // the lower bound's components, largest first
  double seconds = 0;
  std::shared_ptr<CountRecords> records;  // with CountConfig::certificate or keep_records
};

// Refuses (ModelError-free std::invalid_argument) models with `factor` statements: a user
// factor may vanish at nonsingular configurations. With `constraint`s the aspects counted are
// the components of the feasible nonsingular configurations (FORMAT.md, "Counting", C7).
CountResult count_aspects(Model& model, const CountConfig& config);

}  // namespace aspects
