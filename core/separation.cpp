#include "separation.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace aspects {

SignSeparation::SignSeparation(int boxes, int p, const std::vector<int8_t>& signs)
    : boxes_(boxes), p_(p), signs_(signs), parent_(size_t(1) << p), rank_(size_t(1) << p) {
  // A forest only for the classes some box is in: a factor of fixed sign (3-RPR's
  // diagonal of Fq, −2 q_i with q_i ≥ 10) empties half of the classes, and at eps 0.3
  // each forest costs 79 MB. The boxes have at most 3^p distinct sign vectors.
  std::vector<uint8_t> seen(size_t(std::pow(3, p)), 0);
  for (int32_t b = 0; b < boxes; ++b) {
    size_t code = 0;
    for (int i = 0; i < p; ++i) code = 3 * code + size_t(signs[size_t(b) * p + i] + 1);
    seen[code] = 1;
  }
  std::vector<uint8_t> used(parent_.size(), 0);
  for (size_t code = 0; code < seen.size(); ++code) {
    if (!seen[code]) continue;
    std::vector<int8_t> sign(p);
    for (int i = p - 1, c = int(code); i >= 0; --i, c /= 3) sign[i] = int8_t(c % 3 - 1);
    for (size_t s = 0; s < used.size(); ++s) {
      bool ok = true;
      for (int i = 0; i < p; ++i) ok = ok && sign[i] != ((s >> i) & 1 ? -1 : 1);
      used[s] = used[s] || ok;
    }
  }
  for (size_t s = 0; s < parent_.size(); ++s) {
    if (!used[s]) continue;
    parent_[s].resize(boxes);
    std::iota(parent_[s].begin(), parent_[s].end(), 0);
    rank_[s].assign(boxes, 0);
  }
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
    if (parent_[s].empty()) return;  // no box in the class
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
    if (parent_[s].empty()) continue;  // no box in the class, none counted
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
