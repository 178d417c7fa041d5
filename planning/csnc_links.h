// The solution boxes of one CSNC, their neighbours (boxes that may share a point, modulo
// 2π on periodic variables), and P3 (proofs/link.h) proved on demand between two of them
// and remembered. The result index keeps only the links the solve proved (a spanning
// forest unless --all-links); a path may use any link this class proves again.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <tuple>
#include <vector>

#include "link.h"
#include "loaded_result.h"

namespace aspects {

struct BoxNeighbor {
  size_t other = 0;         // index into ResultIndex::solutions
  uint32_t shift_code = 0;  // NeighborPair's code: `other` + 2πk meets this box
};

// A box placed in the unwrapped pose space: its pose part + 2π·shift (pose order).
struct PlacedBox {
  size_t solution = 0;
  std::vector<long> shift;
  bool operator==(const PlacedBox& o) const {
    return solution == o.solution && shift == o.shift;
  }
};

class CsncLinks {
 public:
  CsncLinks(const LoadedResult& r, ModelEvaluator& ev, int32_t csnc);
  int32_t csnc() const { return csnc_; }
  const std::vector<size_t>& boxes() const { return boxes_; }
  // A filter: every pair that meets is listed (ends compared with a margin); P3 decides.
  const std::vector<BoxNeighbor>& neighbors(size_t solution) const;
  // P3 between box a and box b + 2πk (k: shift_code over all variables), proved once;
  // nullptr when it could not be proved. The witness is in a's frame.
  const LinkProof* link(size_t a, size_t b, uint32_t shift_code);
  // Whether a and b, both placed, are linked where their placed pose parts meet: P3 with
  // the pose shift b.shift − a.shift and any shift of the periodic commands.
  bool linked(const PlacedBox& a, const PlacedBox& b);
  // The pose shift (pose order) that a code gives.
  std::vector<long> pose_shift(uint32_t shift_code) const;
  size_t proofs_tried() const { return proofs_.size(); }

 private:
  void find_neighbors();
  const LoadedResult& r_;
  ModelEvaluator& ev_;
  int32_t csnc_;
  std::vector<size_t> boxes_;
  std::vector<std::vector<BoxNeighbor>> neighbors_;  // by solution index (empty outside)
  std::map<std::tuple<size_t, size_t, uint32_t>, std::optional<LinkProof>> proofs_;
  HsWorkspace ws_;
};

}  // namespace aspects
