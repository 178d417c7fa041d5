#include "csnc_links.h"

#include <algorithm>
#include <cmath>

namespace aspects {

CsncLinks::CsncLinks(const LoadedResult& r, ModelEvaluator& ev, int32_t csnc)
    : r_(r), ev_(ev), csnc_(csnc), neighbors_(r.index.solutions.size()) {
  for (size_t i = 0; i < r.index.solutions.size(); ++i)
    if (r.index.solutions[i].csnc == csnc) boxes_.push_back(i);
  find_neighbors();
}

const std::vector<BoxNeighbor>& CsncLinks::neighbors(size_t solution) const {
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

void CsncLinks::find_neighbors() {
  const Model& m = r_.model;
  const auto& sol = r_.index.solutions;
  const int nv = int(r_.index.nv);
  // Sweep on the non-periodic variable whose boxes are narrowest against its spread (the
  // fewest boxes overlap there); with none, every pair is tried.
  int sweep = -1;
  double best = 0;
  for (int v = 0; v < nv; ++v) {
    if (m.vars[v].periodic || boxes_.empty()) continue;
    double width = 0, lo = sol[boxes_[0]].lo[v], hi = sol[boxes_[0]].hi[v];
    for (size_t i : boxes_) {
      width += sol[i].hi[v] - sol[i].lo[v];
      lo = std::min(lo, sol[i].lo[v]);
      hi = std::max(hi, sol[i].hi[v]);
    }
    const double ratio = width / std::max(hi - lo, 1e-300);
    if (sweep < 0 || ratio < best) sweep = v, best = ratio;
  }
  std::vector<size_t> order = boxes_;
  if (sweep >= 0)
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return sol[a].lo[sweep] < sol[b].lo[sweep]; });
  std::vector<unsigned> masks(nv);
  for (size_t x = 0; x < order.size(); ++x) {
    const IndexSolutionBox& a = sol[order[x]];
    for (size_t y = x + 1; y < order.size(); ++y) {
      const IndexSolutionBox& b = sol[order[y]];
      if (sweep >= 0 && b.lo[sweep] > a.hi[sweep] + 1e-9 * (1 + std::fabs(a.hi[sweep]))) break;
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
      for (uint32_t c : codes) {
        uint32_t back = 0;  // a + 2π(−k) meets b
        for (int v = 0; v < nv; ++v) back |= uint32_t(2 - ((c >> (2 * v)) & 3u)) << (2 * v);
        neighbors_[order[x]].push_back({order[y], c});
        neighbors_[order[y]].push_back({order[x], back});
      }
    }
  }
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
  for (const BoxNeighbor& nb : neighbors_[a.solution])
    if (nb.other == b.solution && pose_shift(nb.shift_code) == k &&
        link(a.solution, b.solution, nb.shift_code))
      return true;
  return false;
}

}  // namespace aspects
