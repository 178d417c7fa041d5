#include "csnc_links.h"

#include <algorithm>
#include <cmath>

namespace aspects {

CsncLinks::CsncLinks(const LoadedResult& r, ModelEvaluator& ev, int32_t csnc)
    : r_(r), ev_(ev), csnc_(csnc), neighbors_(r.index.solutions.size()),
      found_(r.index.solutions.size(), 0) {
  for (size_t i = 0; i < r.index.solutions.size(); ++i)
    if (r.index.solutions[i].csnc == csnc) boxes_.push_back(i);
  build_grid();
}

const std::vector<BoxNeighbor>& CsncLinks::neighbors(size_t solution) {
  if (!found_[solution]) {
    neighbors_[solution] = find_neighbors(solution);
    found_[solution] = 1;
  }
  return neighbors_[solution];
}

std::vector<long> CsncLinks::pose_shift(uint32_t code) const {
  std::vector<long> k;
  for (int v : r_.model.pose) k.push_back(long((code >> (2 * v)) & 3u) - 1);
  return k;
}

namespace {

// The shifts k of b (k = 0 only on a non-periodic variable) with a ∩ (b + 2πk) ≠ ∅, as
// bits 1 << (k + 1), ends compared with a margin far above rounding: a filter, P3 decides.
unsigned meeting_shifts(double alo, double ahi, double blo, double bhi, bool periodic) {
  unsigned ks = 0;
  const double margin = 1e-9 * (1 + std::max({std::fabs(alo), std::fabs(ahi), std::fabs(blo),
                                              std::fabs(bhi)}));
  for (int k = periodic ? -1 : 0; k <= (periodic ? 1 : 0); ++k) {
    const double s = 2 * M_PI * k;
    if (blo + s <= ahi + margin && alo <= bhi + s + margin) ks |= 1u << (k + 1);
  }
  return ks;
}

}  // namespace

void CsncLinks::build_grid() {
  const Model& m = r_.model;
  const auto& sol = r_.index.solutions;
  const int nv = int(r_.index.nv);
  for (int v = 0; v < nv && grid_vars_.size() < 2; ++v) {
    if (m.vars[v].periodic || boxes_.empty()) continue;
    double lo = sol[boxes_[0]].lo[v], hi = sol[boxes_[0]].hi[v];
    std::vector<double> widths;
    for (size_t i : boxes_) {
      lo = std::min(lo, sol[i].lo[v]);
      hi = std::max(hi, sol[i].hi[v]);
      widths.push_back(sol[i].hi[v] - sol[i].lo[v]);
    }
    std::nth_element(widths.begin(), widths.begin() + widths.size() / 2, widths.end());
    // Cells about twice the median width, at most 4096 along a variable.
    const double step = std::max({2 * widths[widths.size() / 2], (hi - lo) / 4096, 1e-300});
    grid_vars_.push_back(v);
    origin_.push_back(lo);
    step_.push_back(step);
    extent_.push_back(int64_t((hi - lo) / step) + 1);
  }
  for (size_t i : boxes_)
    for (int64_t c : cells_of(sol[i], 0)) grid_[c].push_back(i);
}

// The keys of the cells that [lo − margin, hi + margin] of box b meets.
std::vector<int64_t> CsncLinks::cells_of(const IndexSolutionBox& b, double margin) const {
  std::vector<int64_t> keys{0};
  for (size_t g = 0; g < grid_vars_.size(); ++g) {
    const int v = grid_vars_[g];
    auto cell = [&](double x) {
      return std::clamp(int64_t(std::floor((x - origin_[g]) / step_[g])), int64_t(0), extent_[g] - 1);
    };
    const int64_t from = cell(b.lo[v] - margin), to = cell(b.hi[v] + margin);
    std::vector<int64_t> next;
    for (int64_t k : keys)
      for (int64_t c = from; c <= to; ++c) next.push_back(k * extent_[g] + c);
    keys.swap(next);
  }
  return keys;
}

std::vector<BoxNeighbor> CsncLinks::find_neighbors(size_t solution) const {
  const Model& m = r_.model;
  const auto& sol = r_.index.solutions;
  const int nv = int(r_.index.nv);
  const IndexSolutionBox& a = sol[solution];
  double scale = 1;
  for (int v = 0; v < nv; ++v) scale = std::max({scale, std::fabs(a.lo[v]), std::fabs(a.hi[v])});
  std::vector<size_t> candidates;
  for (int64_t key : cells_of(a, 1e-9 * scale)) {
    auto it = grid_.find(key);
    if (it != grid_.end()) candidates.insert(candidates.end(), it->second.begin(), it->second.end());
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  std::vector<BoxNeighbor> out;
  std::vector<unsigned> masks(nv);
  for (size_t o : candidates) {
    if (o == solution) continue;
    const IndexSolutionBox& b = sol[o];
    bool meet = true;
    for (int v = 0; v < nv && meet; ++v)
      meet = (masks[v] = meeting_shifts(a.lo[v], a.hi[v], b.lo[v], b.hi[v], m.vars[v].periodic)) != 0;
    if (!meet) continue;
    // Every combination of the meeting shifts, one code each.
    std::vector<uint32_t> codes{0};
    for (int v = 0; v < nv; ++v) {
      std::vector<uint32_t> next;
      for (uint32_t c : codes)
        for (int k = -1; k <= 1; ++k)
          if (masks[v] & (1u << (k + 1))) next.push_back(c | (uint32_t(k + 1) << (2 * v)));
      codes.swap(next);
    }
    for (uint32_t c : codes) out.push_back({o, c});
  }
  return out;
}

const LinkProof* CsncLinks::link(size_t a, size_t b, uint32_t code) {
  auto key = std::make_tuple(a, b, code);
  auto it = proofs_.find(key);
  if (it == proofs_.end()) {
    const ResultIndex& idx = r_.index;
    BoxStore pair(int(idx.nv));
    for (size_t s : {a, b}) {
      Box box(idx.nv);
      for (size_t v = 0; v < idx.nv; ++v)
        box[v].set_hull(idx.solutions[s].lo[v], idx.solutions[s].hi[v]);
      pair.push(box);
    }
    LinkProof proof;
    std::optional<LinkProof> got;
    if (certify_link(ev_, pair, NeighborPair{0, 1, code}, idx.tau, proof, ws_)) got = proof;
    it = proofs_.emplace(key, std::move(got)).first;
  }
  return it->second ? &*it->second : nullptr;
}

bool CsncLinks::linked(const PlacedBox& a, const PlacedBox& b) {
  std::vector<long> k(a.shift.size());
  for (size_t j = 0; j < k.size(); ++j) k[j] = b.shift[j] - a.shift[j];
  for (const BoxNeighbor& nb : neighbors(a.solution))
    if (nb.other == b.solution && pose_shift(nb.shift_code) == k &&
        link(a.solution, b.solution, nb.shift_code))
      return true;
  return false;
}

}  // namespace aspects
