// The whole method of paper Section 4: branch and prune with Prove = P1 ∧ P2 (4.2),
// neighbourhood graph and certified links P3 (4.3), CSNCs and filtering (4.4.1),
// separation and the lower bound (4.4.2).
//
// Guarantees of the result:
//  - every solution box S: ∀x ∈ [x] ∃! q ∈ [q] f(x,q) = 0 (P1), Fx, Fq nonsingular
//    on the box (P2), and every additional constraint holds on the whole box;
//  - every certified link: the two boxes share a solution (P3);
//  - S ∪ U covers every feasible solution of f = 0 in the initial domain (coverage):
//    discarded boxes hold no point satisfying f = 0 and the constraints. The lower
//    bound relies on it.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "search/bisector.h"
#include "search/box_store.h"
#include "search/branch_and_prune.h"
#include "certificate_sink.h"
#include "aspects/components.h"
#include "aspects/cuspidality.h"
#include "hansen_sengupta.h"
#include "link.h"
#include "model/model.h"
#include "aspects/neighborhood_graph.h"
#include "aspects/separation.h"
#include "solution_box.h"
#include "search/verdict.h"

namespace aspects {

struct SearchState;

struct AspectsConfig {
  double eps = 0.1;
  double tau = 1.01;
  int max_newton_iterations = 8;
  bool keep_link_proofs = true;       // P3 data, for the certificate
  // Prove every link between neighbouring solution boxes, or only those that join two
  // components not yet joined (a spanning forest: the same CSNCs, far fewer proofs).
  bool all_links = false;
  int threads = 1;
  BisectorKind bisector = BisectorKind::RoundRobin;
  int defer_depth = 8;  // subtrees below this depth are searched in parallel
  CertificateSink* certificate = nullptr;  // receives the tree records while solving
  // Limits and signals (core/search/stop_condition.h): when it says stop, the cells not yet
  // searched are kept as unexplored output boxes and the rest of the method runs as usual.
  StopCondition* stop = nullptr;
  // Resuming (proofs/search_state.h): the parts already searched are taken from here,
  // the others searched; the state is consumed (empty on return).
  SearchState* resume = nullptr;
  // Called every `checkpoint_seconds` while subtrees are searched, and once more when the
  // search stopped early, with the state and which subtrees are done (a snapshot: parts
  // not done may be changing). From a worker thread, never two calls at once.
  std::function<void(const SearchState&, const std::vector<uint8_t>& done)> checkpoint;
  double checkpoint_seconds = 0;
  std::function<void(const SearchStats&)> progress;
};

enum class UndecidedKind : uint8_t {
  NoExistence = 0,  // P1 not proved (red in the paper's figures)
  Singular = 1,     // P1 proved, P2 not (black)
  Constraint = 2,   // on the boundary of an additional constraint (blue, paper 5.4)
  Unexplored = 3,   // the search stopped before this cell: not a verdict at all
};

// Why the search decided what it did: for tuning and for the user, not for any claim.
struct SearchDiagnostics {
  VerdictCounts attempts{};   // Prove's verdict on every box that survived Prune
  VerdictCounts undecided{};  // the verdict on each undecided leaf
  long refuted_by_equation = 0, refuted_by_newton = 0, refuted_by_constraint = 0;
  void add(const SearchDiagnostics& o);
};

struct AspectsResult {
  std::vector<Factor> factors;
  BoxStore boxes;                       // R = S ∪ U, output order
  std::vector<uint8_t> certified;       // 1: solution box
  std::vector<UndecidedKind> undecided_kind;
  std::vector<int8_t> signs;            // factors.size() per box
  std::vector<SearchNode> tree;
  // N's pairs, in the order proved (M itself is never held: neighbor_count counts it).
  std::vector<NeighborPair> neighbors;
  size_t neighbor_count = 0;            // |M|
  std::vector<int32_t> certified_links; // indices into neighbors: N (0, 1, 2, ...)
  LinkRecords link_proofs;              // parallel to certified_links (if kept)
  std::vector<int32_t> csnc;            // box -> CSNC (decreasing size), -1 for undecided
  std::vector<int64_t> csnc_sizes;
  int filtered = 0;
  CuspidalWitnesses cuspidal;           // cuspidality witnesses per CSNC (both kinds)
  SeparationResult separation;
  SearchDiagnostics diagnostics;
  long solutions = 0, undecided = 0, discarded = 0, processed = 0;
  // A stopped search: `unexplored` output boxes are cells never searched (certified 0,
  // undecided_kind Unexplored); every claim above still holds, the bound counting them
  // like undecided boxes.
  long unexplored = 0;
  StopReason stopped_by = StopReason::None;
  bool complete() const { return stopped_by == StopReason::None; }
  double seconds = 0;
  std::vector<std::pair<std::string, double>> phase_seconds;  // wall time per phase
  // The process's peak resident memory at the end of each phase (MiB): which phase
  // raised the peak.
  std::vector<std::pair<std::string, double>> phase_peak_mib;
};

AspectsResult compute_aspects(Model& model, const AspectsConfig& config);

}  // namespace aspects
