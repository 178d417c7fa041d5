// The solution boxes of one CSNC, their neighbours (boxes that may share a point, modulo
// 2π on periodic variables), and P3 (proofs/link.h) proved on demand between two of them
// and remembered. The result index keeps only the links the solve proved (a spanning
// forest unless --all-links); a path may use any link this class proves again.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "link.h"
#include "results/loaded_result.h"

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
  // A filter: every box that meets this one is listed (ends compared with a margin); P3
  // decides. Found on first use, through a grid over the non-periodic variables, so only
  // the boxes near the route are visited.
  const std::vector<BoxNeighbor>& neighbors(size_t solution);
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
  void build_grid();
  std::vector<int64_t> cells_of(const IndexSolutionBox& b, double margin) const;
  std::vector<BoxNeighbor> find_neighbors(size_t solution) const;
  const LoadedResult& r_;
  ModelEvaluator& ev_;
  int32_t csnc_;
  std::vector<size_t> boxes_;
  std::vector<std::vector<BoxNeighbor>> neighbors_;  // by solution index, once found
  std::vector<char> found_;
  // The grid: up to 2 non-periodic variables, a cell `step` wide from `origin` on each;
  // cell key → the CSNC's boxes that meet the cell. With no such variable, one cell.
  std::vector<int> grid_vars_;
  std::vector<double> origin_, step_;
  std::vector<int64_t> extent_;  // cells along each grid variable
  std::unordered_map<int64_t, std::vector<size_t>> grid_;
  std::map<std::tuple<size_t, size_t, uint32_t>, std::optional<LinkProof>> proofs_;
  HsWorkspace ws_;
};

}  // namespace aspects
