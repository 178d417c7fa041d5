#include "separation_phase.h"

#include <algorithm>

namespace aspects {

SeparationPhase::SeparationPhase(const OutputBoxes& boxes, Parallel& parallel)
    : boxes_(boxes), parallel_(parallel),
      classes_(SignSeparation::counting_classes(boxes.size(), boxes.factors(),
                                                boxes.sign_column(), boxes.certified_column())),
      per_pass_(std::max<size_t>(1, (size_t(1) << 30) / (5 * size_t(std::max(1, boxes.size()))))),
      first_(boxes.size(), boxes.factors(), boxes.sign_column(), pass_classes(0)) {}

std::vector<uint32_t> SeparationPhase::pass_classes(size_t first) const {
  const size_t last = std::min(classes_.size(), first + per_pass_);
  return std::vector<uint32_t>(classes_.begin() + first, classes_.begin() + last);
}

void SeparationPhase::add(const std::vector<NeighborPair>& piece) {
  first_.add(piece, parallel_.for_each());
}

SeparationResult SeparationPhase::finish(bool first_pass_complete,
                                         const std::vector<SearchNode>& tree,
                                         const std::vector<bool>& periodic,
                                         const std::vector<int32_t>& csnc,
                                         const AspectsConfig& config) {
  if (!first_pass_complete) {
    SeparationResult trivial;
    trivial.lower_bound = classes_.empty() ? 0 : 1;
    return trivial;
  }
  SeparationResult total = first_.result(boxes_.certified_column(), &csnc);
  for (size_t c = per_pass_; c < classes_.size(); c += per_pass_) {
    SignSeparation more(boxes_.size(), boxes_.factors(), boxes_.sign_column(), pass_classes(c));
    const bool whole = stream_neighbor_pairs(
        tree, boxes_.ends(), periodic,
        [&](const std::vector<NeighborPair>& piece) { more.add(piece, parallel_.for_each()); },
        parallel_.for_each(), [&] { return config.stopped(); });
    if (!whole) break;
    merge_separation(total, more.result(boxes_.certified_column(), &csnc));
  }
  return total;
}

}  // namespace aspects
