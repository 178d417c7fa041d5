#include "separation.h"

#include <algorithm>
#include <boost/pending/disjoint_sets.hpp>

namespace aspects {

SeparationResult separate_by_signs(int boxes, int p, const std::vector<int8_t>& signs,
                                   const std::vector<uint8_t>& certified,
                                   const std::vector<NeighborPair>& M,
                                   const std::vector<int32_t>* csnc) {
  SeparationResult out;
  const int classes = 1 << p;
  out.per_class.assign(classes, 0);
  std::vector<int> rank(boxes), parent(boxes);
  std::vector<int32_t> counted(boxes);  // per root: 0, or 1 + index in representatives
  std::vector<uint8_t> in_class(boxes);
  for (int s = 0; s < classes; ++s) {
    auto compatible = [&](int b) {
      for (int i = 0; i < p; ++i) {
        int want = (s >> i) & 1 ? 1 : -1;
        if (signs[size_t(b) * p + i] == -want) return false;
      }
      return true;
    };
    auto exact = [&](int b) {
      for (int i = 0; i < p; ++i)
        if (signs[size_t(b) * p + i] != ((s >> i) & 1 ? 1 : -1)) return false;
      return true;
    };
    boost::disjoint_sets<int*, int*> ds(rank.data(), parent.data());
    for (int b = 0; b < boxes; ++b) {
      in_class[b] = compatible(b);
      ds.make_set(b);
    }
    for (const auto& e : M)
      if (in_class[e.a] && in_class[e.b]) ds.union_set(e.a, e.b);
    std::fill(counted.begin(), counted.end(), 0);
    for (int b = 0; b < boxes; ++b) {
      if (!in_class[b] || !certified[b] || !exact(b)) continue;
      int root = ds.find_set(b);
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

}  // namespace aspects
