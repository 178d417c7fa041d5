#include "separation.h"

#include <algorithm>
#include <numeric>

namespace aspects {

SignSeparation::SignSeparation(int boxes, int p, const std::vector<int8_t>& signs)
    : boxes_(boxes), p_(p), signs_(signs), parent_(size_t(1) << p), rank_(size_t(1) << p) {
  for (auto& par : parent_) {
    par.resize(boxes);
    std::iota(par.begin(), par.end(), 0);
  }
  for (auto& r : rank_) r.assign(boxes, 0);
}

// In class s, box b is in R^s unless some factor certainly has the opposite sign.
bool SignSeparation::compatible(int s, int32_t b) const {
  for (int i = 0; i < p_; ++i) {
    int want = (s >> i) & 1 ? 1 : -1;
    if (signs_[size_t(b) * p_ + i] == -want) return false;
  }
  return true;
}

bool SignSeparation::exact(int s, int32_t b) const {
  for (int i = 0; i < p_; ++i)
    if (signs_[size_t(b) * p_ + i] != ((s >> i) & 1 ? 1 : -1)) return false;
  return true;
}

int32_t SignSeparation::find(int s, int32_t b) {
  std::vector<int32_t>& par = parent_[s];
  while (par[b] != b) {
    par[b] = par[par[b]];
    b = par[b];
  }
  return b;
}

void SignSeparation::add(const std::vector<NeighborPair>& pairs, const ForEachIndex& for_each) {
  for_each(int(parent_.size()), [&](int32_t s) {
    std::vector<int32_t>& par = parent_[s];
    std::vector<uint8_t>& rank = rank_[s];
    for (const NeighborPair& e : pairs) {
      if (!compatible(s, e.a) || !compatible(s, e.b)) continue;
      int32_t ra = find(s, e.a), rb = find(s, e.b);
      if (ra == rb) continue;
      if (rank[ra] < rank[rb]) std::swap(ra, rb);
      par[rb] = ra;
      rank[ra] += rank[ra] == rank[rb];
    }
  });
}

SeparationResult SignSeparation::result(const std::vector<uint8_t>& certified,
                                        const std::vector<int32_t>* csnc) {
  SeparationResult out;
  const int classes = int(parent_.size());
  out.per_class.assign(classes, 0);
  std::vector<int32_t> counted(boxes_);  // per root: 0, or 1 + index in representatives
  for (int s = 0; s < classes; ++s) {
    std::fill(counted.begin(), counted.end(), 0);
    for (int32_t b = 0; b < boxes_; ++b) {
      if (!certified[b] || !exact(s, b)) continue;
      int32_t root = find(s, b);
      if (!counted[root]) {
        out.representatives.push_back(-1);
        counted[root] = int32_t(out.representatives.size());
        ++out.per_class[s];
      }
      // CSNCs are numbered by decreasing size: the smallest index is the largest.
      int32_t& rep = out.representatives[counted[root] - 1];
      if (csnc && (*csnc)[b] >= 0 && (rep < 0 || (*csnc)[b] < rep)) rep = (*csnc)[b];
    }
    out.lower_bound += out.per_class[s];
  }
  std::sort(out.representatives.begin(), out.representatives.end());
  return out;
}

SeparationResult separate_by_signs(int boxes, int p, const std::vector<int8_t>& signs,
                                   const std::vector<uint8_t>& certified,
                                   const std::vector<NeighborPair>& M,
                                   const std::vector<int32_t>* csnc) {
  SignSeparation sep(boxes, p, signs);
  sep.add(M);
  return sep.result(certified, csnc);
}

}  // namespace aspects
