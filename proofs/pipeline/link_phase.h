// Phase 2b, certified links (paper 4.3.2, P3) between neighbouring solution boxes, fed the
// pairs of M as the neighbourhood graph streams them. Unless all links are asked for, a
// link is proved only when it joins two components not yet joined (a spanning forest: the
// same CSNCs, far fewer proofs). The pairs are proved in rounds of blocks in parallel;
// each round's blocks read the components known at the round's start (and their own
// links), then join theirs in order: the links proved do not depend on the number of
// threads. Stopped, it keeps the links proved so far: every one is certified, the CSNCs
// they make are only smaller.
#pragma once

#include <cstdint>
#include <vector>

#include "aspects/neighborhood_graph.h"
#include "aspects_config.h"
#include "link.h"
#include "model/model.h"
#include "parallel.h"
#include "search/output_boxes.h"

namespace aspects {

struct LinkOutcome {
  std::vector<NeighborPair> neighbors;   // N's pairs, in the order proved
  std::vector<int32_t> certified_links;  // indices into neighbors: 0, 1, 2, ...
  LinkRecords link_proofs;               // parallel to certified_links (if kept)
};

class LinkPhase {
 public:
  LinkPhase(const Model& m, const AspectsConfig& c, const OutputBoxes& boxes, Parallel& parallel);
  // A piece of M: its pairs between solution boxes are proved in rounds.
  void add(const std::vector<NeighborPair>& piece);
  // Proves what is left (unless stopped) and hands over the links.
  LinkOutcome finish();

 private:
  void round(size_t count);
  int32_t joined_root(int32_t x) const;

  const Model& m_;
  const AspectsConfig& c_;
  const OutputBoxes& boxes_;
  Parallel& parallel_;
  const long prec_;
  // The components joined so far (Boost's disjoint sets over the boxes, ranks below
  // log2 of the box count: a byte each), changed only between rounds.
  std::vector<uint8_t> rank_;
  std::vector<int> parent_;
  // M's pairs between solution boxes, in M's order; from first_ on not yet tried.
  std::vector<NeighborPair> candidates_;
  size_t first_ = 0;
  LinkOutcome out_;
};

}  // namespace aspects
