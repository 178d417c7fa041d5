#include "separation.h"

#include <boost/pending/disjoint_sets.hpp>

namespace aspects {

SeparationResult separate_by_signs(int boxes, int p, const std::vector<int8_t>& signs,
                                   const std::vector<uint8_t>& certified,
                                   const std::vector<NeighborPair>& M) {
  SeparationResult out;
  const int classes = 1 << p;
  out.per_class.assign(classes, 0);
  std::vector<int> rank(boxes), parent(boxes);
  std::vector<uint8_t> counted(boxes);
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
        counted[root] = 1;
        ++out.per_class[s];
      }
    }
    out.lower_bound += out.per_class[s];
  }
  return out;
}

}  // namespace aspects
