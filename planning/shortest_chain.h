// The shortest chain of linked boxes of one CSNC from a start pose to a goal pose: A* over
// the CSNC's neighbouring boxes, weighted by the pose distance from box centre to the
// middle of the two boxes' common pose part to box centre, the links proved (P3) only when
// a chain found uses them; a link that fails is dropped and the search runs again.
#pragma once

#include <vector>

#include "csnc_links.h"

namespace aspects {

struct ChainLink {
  size_t a = 0, b = 0;      // the chain goes from box a to box b
  uint32_t shift_code = 0;  // b + 2πk meets a
  const LinkProof* proof = nullptr;
};

struct Chain {
  std::vector<size_t> boxes;     // solution indices, start to goal
  std::vector<ChainLink> links;  // boxes.size() − 1
};

// False when no chain of proved links joins a box holding `from` to one holding `to`.
bool shortest_chain(const LoadedResult& r, CsncLinks& links, const std::vector<double>& from,
                    const std::vector<double>& to, const std::vector<size_t>& from_boxes,
                    const std::vector<size_t>& to_boxes, Chain& chain);

}  // namespace aspects
