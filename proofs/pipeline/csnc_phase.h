// Phase 3, CSNCs (paper 4.4.1): the connected components of the certified graph (S, N),
// numbered by decreasing size, and the size-ratio filter (a heuristic: it decides what is
// shown, never what is certified).
#pragma once

#include <cstdint>
#include <vector>

#include "aspects/neighborhood_graph.h"
#include "search/output_boxes.h"

namespace aspects {

struct CsncOutcome {
  std::vector<int32_t> csnc;  // box -> CSNC, -1 for an undecided box
  std::vector<int64_t> sizes;
  int filtered = 0;           // the first `filtered` CSNCs are kept by the filter
};

// `links`: indices into `neighbors` of the certified links.
CsncOutcome csnc_phase(const OutputBoxes& boxes, const std::vector<NeighborPair>& neighbors,
                       const std::vector<int32_t>& links);

}  // namespace aspects
