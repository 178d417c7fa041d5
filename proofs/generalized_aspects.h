// The whole method of paper Section 4, as a sequence of phases (proofs/pipeline/, a file
// each): the search, branch and prune with Prove = P1 ∧ P2 (4.2); the neighbourhood graph
// (4.3.1) streamed into the certified links P3 (4.3.2) and the separation's first pass;
// CSNCs and filtering (4.4.1); separation and the lower bound (4.4.2); cuspidality and
// assembly witnesses (3.2). Each phase asks the stop condition.
//
// Guarantees of the result:
//  - every solution box S: ∀x ∈ [x] ∃! q ∈ [q] f(x,q) = 0 (P1), Fx, Fq nonsingular
//    on the box (P2), and every additional constraint holds on the whole box;
//  - every certified link: the two boxes share a solution (P3);
//  - S ∪ U covers every feasible solution of f = 0 in the initial domain (coverage):
//    discarded boxes hold no point satisfying f = 0 and the constraints. The lower
//    bound relies on it.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "aspects/cuspidality.h"
#include "aspects/neighborhood_graph.h"
#include "aspects/separation.h"
#include "link.h"
#include "model/determinant_factors.h"
#include "model/model.h"
#include "pipeline/aspects_config.h"
#include "pipeline/aspects_search.h"
#include "search/output_boxes.h"
#include "search/stop_condition.h"

namespace aspects {

struct AspectsResult {
  std::vector<Factor> factors;
  OutputBoxes boxes;                    // R = S ∪ U, output order, with their signs
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
  // A stopped search: `unexplored` output boxes are cells never searched (undecided, kind
  // Unexplored); every claim above still holds, the bound counting them like undecided
  // boxes. A run stopped after the search keeps what each phase established (see
  // proofs/pipeline/): fewer links, a smaller bound, fewer witnesses; every claim holds.
  long unexplored = 0;
  StopReason stopped_by = StopReason::None;
  std::string stopped_in;  // the phase (summary.json's name) during which it stopped
  // The first phase after the search that a stop of the whole run cut (empty: they all ran
  // whole, as after a spent max-boxes budget or a first Ctrl-C, which stop the search only).
  std::string run_stopped_in;
  bool complete() const { return stopped_by == StopReason::None; }
  double seconds = 0;
  std::vector<std::pair<std::string, double>> phase_seconds;  // wall time per phase
  // The process's peak resident memory at the end of each phase (MiB): which phase
  // raised the peak.
  std::vector<std::pair<std::string, double>> phase_peak_mib;
};

AspectsResult compute_aspects(Model& model, const AspectsConfig& config);

}  // namespace aspects
