#include "aspects/separation.h"

#include <algorithm>

namespace aspects {

std::vector<uint32_t> SignSeparation::counting_classes(int boxes, int p,
                                                       const std::vector<int8_t>& signs,
                                                       const std::vector<uint8_t>& certified) {
  std::vector<uint32_t> classes;
  for (int32_t b = 0; b < boxes; ++b) {
    if (!certified[b]) continue;
    uint32_t s = 0;
    bool exact = true;
    for (int i = 0; i < p; ++i) {
      const int8_t x = signs[size_t(b) * p + i];
      exact = exact && x != 0;
      s |= uint32_t(x > 0) << i;
    }
    if (exact) classes.push_back(s);
  }
  std::sort(classes.begin(), classes.end());
  classes.erase(std::unique(classes.begin(), classes.end()), classes.end());
  return classes;
}

SignSeparation::SignSeparation(int boxes, int p, const std::vector<int8_t>& signs,
                               std::vector<uint32_t> classes)
    : boxes_(boxes), p_(p), signs_(signs), classes_(std::move(classes)),
      parent_(classes_.size()), rank_(classes_.size()) {
  for (size_t c = 0; c < classes_.size(); ++c) {
    parent_[c].resize(boxes);
    rank_[c].resize(boxes);
    Forest joined = forest(c);
    for (int32_t b = 0; b < boxes; ++b) joined.make_set(b);
  }
}

// In class s, box b is in R^s unless some factor certainly has the opposite sign.
bool SignSeparation::compatible(uint32_t s, int32_t b) const {
  for (int i = 0; i < p_; ++i) {
    int want = (s >> i) & 1 ? 1 : -1;
    if (signs_[size_t(b) * p_ + i] == -want) return false;
  }
  return true;
}

bool SignSeparation::exact(uint32_t s, int32_t b) const {
  for (int i = 0; i < p_; ++i)
    if (signs_[size_t(b) * p_ + i] != ((s >> i) & 1 ? 1 : -1)) return false;
  return true;
}

// Boost's disjoint sets over class c's arrays (a view: it owns nothing).
SignSeparation::Forest SignSeparation::forest(size_t c) {
  return Forest(rank_[c].data(), parent_[c].data());
}

void SignSeparation::add(const std::vector<NeighborPair>& pairs, const ForEachIndex& for_each) {
  for_each(int(classes_.size()), [&](int32_t c) {
    const uint32_t s = classes_[c];
    Forest joined = forest(c);
    for (const NeighborPair& e : pairs)
      if (compatible(s, e.a) && compatible(s, e.b)) joined.union_set(e.a, e.b);
  });
}

SeparationResult SignSeparation::result(const std::vector<uint8_t>& certified,
                                        const std::vector<int32_t>* csnc) {
  SeparationResult out;
  out.per_class.assign(size_t(1) << p_, 0);
  std::vector<int32_t> counted(boxes_);  // per root: 0, or 1 + index in representatives
  for (size_t c = 0; c < classes_.size(); ++c) {
    const uint32_t s = classes_[c];
    Forest joined = forest(c);
    std::fill(counted.begin(), counted.end(), 0);
    for (int32_t b = 0; b < boxes_; ++b) {
      if (!certified[b] || !exact(s, b)) continue;
      int32_t root = joined.find_set(b);
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

void merge_separation(SeparationResult& total, const SeparationResult& part) {
  total.lower_bound += part.lower_bound;
  if (total.per_class.size() < part.per_class.size()) total.per_class.resize(part.per_class.size());
  for (size_t s = 0; s < part.per_class.size(); ++s) total.per_class[s] += part.per_class[s];
  total.representatives.insert(total.representatives.end(), part.representatives.begin(),
                               part.representatives.end());
  std::sort(total.representatives.begin(), total.representatives.end());
}

SeparationResult separate_by_signs(int boxes, int p, const std::vector<int8_t>& signs,
                                   const std::vector<uint8_t>& certified,
                                   const std::vector<NeighborPair>& M,
                                   const std::vector<int32_t>* csnc) {
  SignSeparation sep(boxes, p, signs, SignSeparation::counting_classes(boxes, p, signs, certified));
  sep.add(M);
  return sep.result(certified, csnc);
}

}  // namespace aspects
