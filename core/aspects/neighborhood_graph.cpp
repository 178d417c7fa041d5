#include "aspects/neighborhood_graph.h"

#include <algorithm>
#include <cmath>

namespace aspects {

uint32_t pack_shift(const std::vector<int>& k) {
  uint32_t c = 0;
  for (size_t v = 0; v < k.size(); ++v) c |= uint32_t(k[v] + 1) << (2 * v);
  return c;
}

namespace {

// Hull of the output boxes below internal tree nodes: a reported box may leave its cell
// (the Newton iterate can shift), so the cells alone cannot guide the search. A filter
// only, so in floats rounded outward, and only for nodes above at least kMinBoxes output
// boxes: below them the query tests the few boxes themselves. A tree has tens of millions
// of nodes; hulls in doubles for all of them would outweigh the boxes.
struct Hulls {
  static constexpr int32_t kMinBoxes = 8;
  const std::vector<SearchNode>& tree;
  const BoxStore& R;
  std::vector<int32_t> slot;  // per node: its hull's index, -1 for none (leaves included)
  std::vector<float> h;       // per hull, lo and hi per variable
  // Per hull, the largest output box id below its node: a query for box a reports only
  // b > a, so it skips the nodes below which every id is at most a (with ids in depth-first
  // order, about half the tree for each query).
  std::vector<int32_t> last;

  static float down(double x) {
    float f = float(x);
    return f > x ? std::nextafter(f, -INFINITY) : f;
  }
  static float up(double x) {
    float f = float(x);
    return f < x ? std::nextafter(f, INFINITY) : f;
  }

  Hulls(const std::vector<SearchNode>& t, const BoxStore& boxes)
      : tree(t), R(boxes), slot(t.size(), 0) {
    const int nv = R.nv();
    // The output boxes below each node, bottom-up (children have larger ids than their
    // parent), held in `slot` until the slots are numbered.
    for (size_t i = tree.size(); i-- > 0;) {
      const SearchNode& s = tree[i];
      slot[i] = s.internal() ? slot[s.left()] + slot[s.right()] : s.leaf() >= 0;
    }
    int32_t hulls = 0;
    for (size_t i = 0; i < tree.size(); ++i)
      slot[i] = tree[i].internal() && slot[i] >= kMinBoxes ? hulls++ : -1;
    // [+inf, -inf] is the empty hull: it meets nothing and is the identity of the union.
    h.resize(size_t(hulls) * 2 * nv);
    for (size_t k = 0; k < h.size(); k += 2) h[k] = INFINITY, h[k + 1] = -INFINITY;
    last.assign(size_t(hulls), -1);
    std::vector<int32_t> stack;  // unite's
    for (size_t i = tree.size(); i-- > 0;)
      if (slot[i] >= 0) {
        float* hull = &h[size_t(slot[i]) * 2 * nv];
        unite(tree[i].left(), hull, last[slot[i]], stack);
        unite(tree[i].right(), hull, last[slot[i]], stack);
      }
  }

  // hull ∪= the output boxes below `node` (whose hull, if it has one, is already made), and
  // last_id := max(last_id, their largest id). Iterative, on `stack` (the union takes any
  // order): a stopped search leaves trees tens of thousands of levels deep.
  void unite(int32_t node, float* hull, int32_t& last_id, std::vector<int32_t>& stack) const {
    const int nv = R.nv();
    stack.assign(1, node);
    while (!stack.empty()) {
      const int32_t i = stack.back();
      stack.pop_back();
      const SearchNode& s = tree[i];
      if (s.internal() && slot[i] < 0) {
        stack.push_back(s.right());
        stack.push_back(s.left());
        continue;
      }
      if (!s.internal() && s.leaf() < 0) continue;
      last_id = std::max(last_id, s.internal() ? last[slot[i]] : s.leaf());
      for (int v = 0; v < nv; ++v) {
        float lo, hi;
        if (s.internal()) {
          lo = h[(size_t(slot[i]) * nv + v) * 2];
          hi = h[(size_t(slot[i]) * nv + v) * 2 + 1];
        } else {
          lo = down(R.lo(s.leaf(), v));
          hi = up(R.hi(s.leaf(), v));
        }
        hull[2 * v] = std::min(hull[2 * v], lo);
        hull[2 * v + 1] = std::max(hull[2 * v + 1], hi);
      }
    }
  }
};

// The certificate's definition of M (certificates/FORMAT.md, "claim lower-bound"): a and b
// are neighbours when, for every v, a_v meets b_v + 2πk_v with the shifted ends of b
// rounded outward to doubles. The checker recomputes M with exactly this test.
bool meets_shifted(const BoxStore& R, int a, int b, const std::vector<int>& k,
                   const Interval& two_pi, Interval& t) {
  for (int v = 0; v < R.nv(); ++v) {
    double lo = R.lo(b, v), hi = R.hi(b, v);
    if (k[v] != 0) {
      mpfi_mul_si(t.get(), two_pi.get(), k[v]);
      mpfi_add_d(t.get(), t.get(), lo);
      lo = t.lo_down();
      mpfi_mul_si(t.get(), two_pi.get(), k[v]);
      mpfi_add_d(t.get(), t.get(), hi);
      hi = t.hi_up();
    }
    if (R.lo(a, v) > hi || lo > R.hi(a, v)) return false;
  }
  return true;
}

struct Query {
  const std::vector<SearchNode>& tree;
  const BoxStore& R;
  const Hulls& hulls;
  std::vector<double> lo, hi;  // query box (shifted, widened): a filter only
  int self;
  std::vector<int> back;       // the shift of b, −k
  const Interval& two_pi;
  Interval t;
  std::vector<NeighborPair>* out;

  std::vector<int32_t> stack;  // visit's, kept from one query to the next

  // The pairs (self, b) below `node`, depth first, left before right. An explicit stack:
  // a stopped search leaves trees tens of thousands of levels deep.
  void visit(int32_t node) {
    const int nv = R.nv();
    stack.assign(1, node);
    while (!stack.empty()) {
      const int32_t i = stack.back();
      stack.pop_back();
      const SearchNode& s = tree[i];
      if (!s.internal()) {
        const int32_t b = s.leaf();
        if (b < 0 || b <= self || !meets_query(b)) continue;
        if (meets_shifted(R, self, b, back, two_pi, t)) out->push_back({self, b, pack_shift(back)});
        continue;
      }
      if (hulls.slot[i] >= 0) {
        if (hulls.last[hulls.slot[i]] <= self) continue;
        const float* h = &hulls.h[size_t(hulls.slot[i]) * 2 * nv];
        bool meets = true;
        for (int v = 0; v < nv && meets; ++v) meets = !(lo[v] > h[2 * v + 1] || h[2 * v] > hi[v]);
        if (!meets) continue;
      }
      stack.push_back(s.right());
      stack.push_back(s.left());
    }
  }

  bool meets_query(int32_t b) const {
    for (int v = 0; v < R.nv(); ++v)
      if (lo[v] > R.hi(b, v) || R.lo(b, v) > hi[v]) return false;
    return true;
  }
};

}  // namespace

bool stream_neighbor_pairs(const std::vector<SearchNode>& tree, const BoxStore& R,
                           const std::vector<bool>& periodic,
                           const std::function<void(const std::vector<NeighborPair>&)>& consume,
                           const ForEachIndex& for_each, const std::function<bool()>& stop) {
  const int nv = R.nv();
  std::vector<int> pvars;
  for (int v = 0; v < nv; ++v)
    if (periodic[v]) pvars.push_back(v);
  int combos = 1;
  for (size_t i = 0; i < pvars.size(); ++i) combos *= 3;
  const Hulls hulls(tree, R);
  Interval two_pi_shared;
  mpfi_const_pi(two_pi_shared.get());
  mpfi_mul_ui(two_pi_shared.get(), two_pi_shared.get(), 2);

  // Blocks of consecutive boxes a, each with its own output: sorted within the block,
  // they follow each other in (a, b) order. A round holds 1/256 of the boxes, so that its
  // pairs stay a small part of M, which may not fit in memory whole.
  const int block = std::max(2048, R.size() / 4096 + 1);
  const int blocks = (R.size() + block - 1) / block, round = 16;
  std::vector<std::vector<NeighborPair>> found(round);
  auto query_block = [&](int32_t blk, std::vector<NeighborPair>& out) {
    // Per block, copies at the shared value's precision (a worker thread's default
    // precision may differ, and M must not depend on the thread).
    Interval two_pi = two_pi_shared, t = two_pi_shared;
    Query q{tree, R, hulls, std::vector<double>(nv), std::vector<double>(nv), 0,
            std::vector<int>(nv, 0), two_pi, two_pi_shared, &out, {}};
    std::vector<int> k(nv, 0);
    const int end = std::min(R.size(), (blk + 1) * block);
    for (int id = blk * block; id < end; ++id) {
      for (int c = 0; c < combos; ++c) {
        int code = c;
        std::fill(k.begin(), k.end(), 0);
        for (int v : pvars) {
          k[v] = code % 3 - 1;
          code /= 3;
        }
        // Query box a + 2πk meets b  ⇔  b − 2πk meets a: b is tested with shift −k. The
        // query only filters (widened by far more than any rounding); meets_shifted
        // decides. No shifted query is skipped: output boxes may leave the domain (a
        // periodic command's image crosses its seam), so one that misses it may still
        // meet a box.
        for (int v = 0; v < nv; ++v) {
          q.back[v] = -k[v];
          if (k[v] == 0) {
            q.lo[v] = R.lo(id, v);
            q.hi[v] = R.hi(id, v);
            continue;
          }
          mpfi_mul_si(t.get(), two_pi.get(), k[v]);
          mpfi_add_d(t.get(), t.get(), R.lo(id, v));
          q.lo[v] = t.lo_down() - 1e-9 * (1 + std::fabs(t.lo_down()));
          mpfi_mul_si(t.get(), two_pi.get(), k[v]);
          mpfi_add_d(t.get(), t.get(), R.hi(id, v));
          q.hi[v] = t.hi_up() + 1e-9 * (1 + std::fabs(t.hi_up()));
        }
        q.self = id;
        q.visit(0);
      }
    }
    // A pair met through two shifts (boxes spanning a whole period) is kept once.
    std::sort(out.begin(), out.end(), [](const NeighborPair& x, const NeighborPair& y) {
      return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.shift_code < y.shift_code;
    });
    out.erase(std::unique(out.begin(), out.end(),
                          [](const NeighborPair& x, const NeighborPair& y) {
                            return x.a == y.a && x.b == y.b;
                          }),
              out.end());
  };
  for (int first = 0; first < blocks; first += round) {
    if (stop && stop()) return false;
    const int n = std::min(round, blocks - first);
    for_each(n, [&](int32_t i) { query_block(first + i, found[i]); });
    for (int i = 0; i < n; ++i) {
      consume(found[i]);
      found[i].clear();
    }
  }
  return true;
}

std::vector<NeighborPair> neighbor_pairs(const std::vector<SearchNode>& tree, const BoxStore& R,
                                         const std::vector<bool>& periodic,
                                         const ForEachIndex& for_each) {
  std::vector<NeighborPair> pairs;
  stream_neighbor_pairs(
      tree, R, periodic,
      [&](const std::vector<NeighborPair>& piece) {
        pairs.insert(pairs.end(), piece.begin(), piece.end());
      },
      for_each);
  return pairs;
}

}  // namespace aspects
