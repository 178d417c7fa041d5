// Phase 4, separation by the signs of the determinant factors (paper 4.4.2) and the
// certified lower bound (11). The first pass takes M while the neighbourhood graph streams
// it (as many sign classes as fit in 1 GiB); the classes left over take passes over M of
// their own. Each class must see all of M: a class whose pass stopped counts nothing, and
// if the first pass stopped, the bound is only what one certified box of certain signs
// proves (one aspect), or 0.
#pragma once

#include <cstdint>
#include <vector>

#include "aspects/neighborhood_graph.h"
#include "aspects/separation.h"
#include "aspects_config.h"
#include "parallel.h"
#include "search/output_boxes.h"

namespace aspects {

class SeparationPhase {
 public:
  SeparationPhase(const OutputBoxes& boxes, Parallel& parallel);
  // A piece of M, for the first pass.
  void add(const std::vector<NeighborPair>& piece);
  // The bound. `first_pass_complete`: the first pass saw all of M. The other passes stream
  // M again (unless stopped), with the CSNCs for the representatives.
  SeparationResult finish(bool first_pass_complete, const std::vector<SearchNode>& tree,
                          const std::vector<bool>& periodic, const std::vector<int32_t>& csnc,
                          const AspectsConfig& config);

 private:
  std::vector<uint32_t> pass_classes(size_t first) const;

  const OutputBoxes& boxes_;
  Parallel& parallel_;
  std::vector<uint32_t> classes_;  // the classes that can count
  size_t per_pass_;
  SignSeparation first_;
};

}  // namespace aspects
