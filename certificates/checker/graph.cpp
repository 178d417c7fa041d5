// graph.cpp — union-find (path halving), the neighbourhood graph by sort-and-sweep (not
// O(N²): items are the boxes and their useful 2π-shifted copies, sorted on the dimension
// where boxes are thinnest relative to their spread; only pairs overlapping there are
// tested), the sign-separated lower bound and the filtering rule.
#include "graph.h"

#include <algorithm>
#include <numeric>

namespace cc {

void UnionFind::reset(size_t n) {
  parent.resize(n);
  std::iota(parent.begin(), parent.end(), 0);
}

int UnionFind::find(int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

void UnionFind::unite(int a, int b) {
  a = find(a), b = find(b);
  if (a != b) parent[std::max(a, b)] = std::min(a, b);
}

std::vector<std::pair<int, int>> neighbour_pairs(const OutBoxes& R, const std::vector<bool>& periodic,
                                                 const Ival& two_pi) {
  const int nv = R.nv;
  const size_t N = R.size();
  std::vector<std::pair<int, int>> out;
  if (N == 0) return out;
  std::vector<int> pv;
  for (int v = 0; v < nv; ++v)
    if (periodic[v]) pv.push_back(v);
  std::vector<double> hlo(nv, 1e308), hhi(nv, -1e308), mean(nv, 0);
  for (size_t b = 0; b < N; ++b)
    for (int v = 0; v < nv; ++v) {
      hlo[v] = std::min(hlo[v], R.box(b)[2 * v]);
      hhi[v] = std::max(hhi[v], R.box(b)[2 * v + 1]);
      mean[v] += (R.box(b)[2 * v + 1] - R.box(b)[2 * v]) / double(N);
    }
  Ival shift[3], t;
  for (int k = -1; k <= 1; ++k) mpfi_mul_si(shift[k + 1], two_pi, k);
  // Items: every box unshifted, and each copy b + 2πk (bounds rounded outward) that can
  // still meet some unshifted box.
  struct Item {
    int id;
    bool shifted;
  };
  std::vector<Item> items;
  std::vector<double> ib, tmp(2 * nv);
  int combos = 1;
  for (size_t i = 0; i < pv.size(); ++i) combos *= 3;
  for (size_t b = 0; b < N; ++b)
    for (int c = 0; c < combos; ++c) {
      std::copy(R.box(b), R.box(b) + 2 * nv, tmp.begin());
      bool useful = true;
      int code = c;
      for (int v : pv) {
        int k = code % 3 - 1;
        code /= 3;
        if (k == 0) continue;
        mpfi_add_d(t, shift[k + 1], tmp[2 * v]);
        tmp[2 * v] = t.lo();
        mpfi_add_d(t, shift[k + 1], tmp[2 * v + 1]);
        tmp[2 * v + 1] = t.hi();
        if (tmp[2 * v + 1] < hlo[v] || tmp[2 * v] > hhi[v]) useful = false;
      }
      if (!useful) continue;
      items.push_back({int(b), c != (combos - 1) / 2});  // code (combos-1)/2 is k = 0
      ib.insert(ib.end(), tmp.begin(), tmp.end());
    }
  int d = 0;
  double best = -1;
  for (int v = 0; v < nv; ++v) {
    double score = (hhi[v] - hlo[v]) / (mean[v] + 1e-300);
    if (score > best) best = score, d = v;
  }
  std::vector<size_t> order(items.size());
  std::iota(order.begin(), order.end(), 0);
  auto box = [&](size_t i) { return &ib[i * 2 * nv]; };
  std::sort(order.begin(), order.end(), [&](size_t x, size_t y) { return box(x)[2 * d] < box(y)[2 * d]; });
  for (size_t i = 0; i < order.size(); ++i) {
    const Item& p = items[order[i]];
    const double* a = box(order[i]);
    for (size_t j = i + 1; j < order.size(); ++j) {
      const Item& q = items[order[j]];
      const double* b = box(order[j]);
      if (b[2 * d] > a[2 * d + 1]) break;  // sorted on lo_d: no later item meets a in d
      if (p.id == q.id || (p.shifted && q.shifted)) continue;
      bool meet = true;
      for (int v = 0; v < nv && meet; ++v) meet = a[2 * v] <= b[2 * v + 1] && b[2 * v] <= a[2 * v + 1];
      if (meet) out.emplace_back(std::min(p.id, q.id), std::max(p.id, q.id));
    }
  }
  return out;
}

long lower_bound(const OutBoxes& R, const std::vector<std::pair<int, int>>& M) {
  const size_t N = R.size();
  const uint32_t full = R.p >= 32 ? ~0u : (1u << R.p) - 1;
  UnionFind uf;
  std::vector<uint8_t> compat(N), counted(N);
  long total = 0;
  for (uint32_t s = 0; s <= full; ++s) {  // bit i of s set: factor i positive
    for (size_t b = 0; b < N; ++b) compat[b] = !(R.neg[b] & s) && !(R.pos[b] & ~s & full);
    uf.reset(N);
    for (const auto& e : M)
      if (compat[e.first] && compat[e.second]) uf.unite(e.first, e.second);
    std::fill(counted.begin(), counted.end(), 0);
    for (size_t b = 0; b < N; ++b) {
      if (!R.solution[b] || R.pos[b] != s || R.neg[b] != (~s & full)) continue;
      int r = uf.find(int(b));
      if (!counted[r]) counted[r] = 1, ++total;
    }
    if (s == full) break;
  }
  return total;
}

long filtered_count(const std::vector<int64_t>& sizes) {
  if (sizes.size() <= 1) return long(sizes.size());
  double best = 0;
  long cut = long(sizes.size());
  for (size_t i = 0; i + 1 < sizes.size(); ++i) {
    double r = double(sizes[i]) / double(sizes[i + 1]);
    if (r > best) best = r, cut = long(i) + 1;
  }
  return best < 2 ? long(sizes.size()) : cut;
}

}  // namespace cc
