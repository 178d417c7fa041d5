// bound.cpp — trusted core: the combinatorial half of the check. A union-find (path
// halving), the neighbourhood graph M by a plain sort-and-sweep tested pair by pair with
// the rule of FORMAT.md, the sign-separated lower bound (11) and the filtering rule.
#include "checker.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

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
  a = find(a);
  b = find(b);
  if (a != b) parent[std::max(a, b)] = std::min(a, b);
}

void shift_by_periods(Ival& t, const Ival& two_pi, int k, double x) {
  mul_d(t, two_pi, k);
  add_d(t, t, x);
}

// The rule of FORMAT.md for a < b: on every variable v, a_v meets b_v + 2πk for some k
// (k = 0 unless v is periodic), the shifted ends of b rounded outward.
static bool meet(const OutBoxes& R, const std::vector<bool>& periodic, const Ival& two_pi,
                 int a, int b) {
  Ival t;
  for (int v = 0; v < R.nv; ++v) {
    const double* x = R.box(a) + 2 * v;
    const double* y = R.box(b) + 2 * v;
    bool any = x[0] <= y[1] && y[0] <= x[1];
    for (int k = -1; k <= 1 && !any && periodic[v]; k += 2) {
      shift_by_periods(t, two_pi, k, y[0]);
      const double lo = t.lo();
      shift_by_periods(t, two_pi, k, y[1]);
      any = x[0] <= t.hi() && lo <= x[1];
    }
    if (!any) return false;
  }
  return true;
}

PlainSweep::PlainSweep(const OutBoxes& R, const std::vector<bool>& periodic, const Ival& two_pi)
    : R_(R), periodic_(periodic), two_pi_(two_pi) {
  // The sweep variable d: where the boxes are thinnest relative to their spread (any d
  // finds every pair; this one proposes fewer).
  int d = 0;
  double best = -1;
  for (int v = 0; v < R.nv; ++v) {
    double lo = 1e308, hi = -1e308, mean = 0;
    for (size_t b = 0; b < R.size(); ++b) {
      lo = std::min(lo, R.box(b)[2 * v]);
      hi = std::max(hi, R.box(b)[2 * v + 1]);
      mean += (R.box(b)[2 * v + 1] - R.box(b)[2 * v]) / double(R.size());
    }
    if ((hi - lo) / (mean + 1e-300) > best) {
      best = (hi - lo) / (mean + 1e-300);
      d = v;
    }
  }
  // A pair of the rule meets with k_d = 0, or with b_d + 2πk_d rounded outward: either
  // way an unshifted item overlaps an item of the other box.
  Ival t;
  for (size_t b = 0; b < R.size(); ++b)
    for (int k = periodic[d] ? -1 : 0; k <= (periodic[d] ? 1 : 0); ++k) {
      shift_by_periods(t, two_pi, k, R.box(b)[2 * d]);
      const double lo = t.lo();
      shift_by_periods(t, two_pi, k, R.box(b)[2 * d + 1]);
      items_.push_back({lo, t.hi(), int(b), k});
    }
  std::sort(items_.begin(), items_.end(), [](const Item& x, const Item& y) { return x.lo < y.lo; });
}

size_t PlainSweep::run(const std::function<void(int, int)>& visit, size_t max_pairs,
                       int) const {
  size_t pairs = 0;
  for (size_t i = 0; i < items_.size(); ++i)
    for (size_t j = i + 1; j < items_.size() && items_[j].lo <= items_[i].hi; ++j) {
      const Item &p = items_[i], &q = items_[j];
      if (p.id == q.id || (p.k && q.k)) continue;
      const int a = std::min(p.id, q.id), b = std::max(p.id, q.id);
      if (!meet(R_, periodic_, two_pi_, a, b)) continue;
      if (++pairs > max_pairs) throw std::length_error("neighbourhood graph");
      visit(a, b);
    }
  return pairs;
}

long lower_bound(const OutBoxes& R, const PairSweep& M, uint32_t use, size_t max_pairs,
                 size_t* pairs, int threads) {
  const size_t N = R.size();
  const uint32_t full = use;
  // Only the sign vectors s of solution boxes with every used sign verified can count (bit
  // i of s set: factor i positive): at most N classes instead of 2^p.
  std::vector<uint32_t> classes;
  for (size_t b = 0; b < N; ++b)
    if (R.solution[b] && ((R.pos[b] | R.neg[b]) & full) == full) classes.push_back(R.pos[b] & full);
  std::sort(classes.begin(), classes.end());
  classes.erase(std::unique(classes.begin(), classes.end()), classes.end());
  // A union-find over M per class: up to 2^20 classes (p = 20 user factors) on 10^5 boxes
  // would take hours. A real certificate has a handful of classes. The steps, classes ×
  // (pairs + boxes), may reach 2^32 + 2^10 per box: a fixed 2^32 rejected 3-RPR at eps 0.1
  // (2 classes, 2.4·10^9 pairs), and a box's proofs cost more than 2^10 union-find steps.
  const double budget = double(uint64_t(1) << 32) + 1024.0 * double(N);
  if (double(classes.size()) * double(N) > budget) throw std::length_error("sign classes");
  // Classes in groups of at most 32 (a bit mask per box) whose union-finds hold at most 2^28
  // entries (1 GiB): one sweep of M per group, and one even without a class, so that every
  // certificate meets the pair limit.
  const size_t per_gib = (size_t(1) << 28) / std::max<size_t>(N, 1);
  const size_t group = std::min<size_t>(32, std::max<size_t>(1, per_gib));
  std::vector<uint8_t> counted(N);
  long total = 0;
  size_t seen = 0;
  for (size_t g0 = 0; g0 == 0 || g0 < classes.size(); g0 += group) {
    const size_t g = std::min(group, classes.size() - g0);
    std::vector<UnionFind> uf(g);
    std::vector<uint32_t> compat(N);  // bit c: box b is compatible with class g0 + c
    for (size_t c = 0; c < g; ++c) {
      const uint32_t s = classes[g0 + c];
      uf[c].reset(N);
      for (size_t b = 0; b < N; ++b)
        if (!(R.neg[b] & s) && !(R.pos[b] & ~s & full)) compat[b] |= uint32_t(1) << c;
    }
    seen = M.run(
        [&](int a, int b) {
          for (uint32_t both = compat[a] & compat[b]; both; both &= both - 1)
            uf[__builtin_ctz(both)].unite(a, b);
        },
        max_pairs, threads);
    if (double(classes.size()) * double(seen + N) > budget) throw std::length_error("sign classes");
    for (size_t c = 0; c < g; ++c) {
      const uint32_t s = classes[g0 + c];
      std::fill(counted.begin(), counted.end(), 0);
      for (size_t b = 0; b < N; ++b) {
        if (!R.solution[b] || (R.pos[b] & full) != s || (R.neg[b] & full) != (~s & full)) continue;
        const int r = uf[c].find(int(b));
        if (counted[r]) continue;
        counted[r] = 1;
        ++total;
      }
    }
  }
  if (pairs) *pairs = seen;
  return total;
}

long filtered_count(const std::vector<int64_t>& sizes) {
  if (sizes.size() <= 1) return long(sizes.size());
  double best = 0;
  long cut = long(sizes.size());
  for (size_t i = 0; i + 1 < sizes.size(); ++i) {
    double r = double(sizes[i]) / double(sizes[i + 1]);
    if (r > best) {
      best = r;
      cut = long(i) + 1;
    }
  }
  return best < 2 ? long(sizes.size()) : cut;
}

}  // namespace cc
