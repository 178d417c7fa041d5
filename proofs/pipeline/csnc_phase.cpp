#include "csnc_phase.h"

#include <utility>

#include "aspects/components.h"

namespace aspects {

CsncOutcome csnc_phase(const OutputBoxes& boxes, const std::vector<NeighborPair>& neighbors,
                       const std::vector<int32_t>& links) {
  std::vector<int32_t> vertex(boxes.size(), -1), box_of;
  for (int b = 0; b < boxes.size(); ++b)
    if (boxes.certified(b)) {
      vertex[b] = int32_t(box_of.size());
      box_of.push_back(b);
    }
  std::vector<std::pair<int32_t, int32_t>> edges;
  for (int32_t e : links) edges.emplace_back(vertex[neighbors[e].a], vertex[neighbors[e].b]);
  Components comps = connected_components(int(box_of.size()), edges);
  CsncOutcome out;
  out.csnc.assign(boxes.size(), -1);
  for (size_t v = 0; v < box_of.size(); ++v) out.csnc[box_of[v]] = comps.of[v];
  out.sizes = std::move(comps.sizes);
  out.filtered = filter_components(out.sizes);
  return out;
}

}  // namespace aspects
