// The solver's neighbourhood graph M must be exactly the graph certificates/FORMAT.md
// defines ("claim lower-bound"), which check_cert recomputes: a pair (a, b), a < b, is in
// M when for every variable v some k_v ∈ {−1, 0, 1} (0 unless v is periodic) gives
// a.lo_v ≤ ⌈b.hi_v + 2πk_v⌉ and ⌊b.lo_v + 2πk_v⌋ ≤ a.hi_v (ends rounded outward to
// doubles). Here M is recomputed by brute force over all pairs of a real solve and
// compared pair by pair; each recorded shift must also satisfy the test.
#include <gtest/gtest.h>

#include <array>
#include <set>
#include <thread>
#include <utility>

#include "deep_tree.h"
#include "generalized_aspects.h"

using namespace aspects;

namespace {

using Ends = std::vector<std::array<double, 2>>;

// Shifted ends of every box: E[(b·nv + v)·3 + k + 1] = {⌊b.lo_v + 2πk⌋, ⌈b.hi_v + 2πk⌉}.
Ends shifted_ends(const BoxStore& R, const std::vector<bool>& periodic) {
  const int nv = R.nv();
  Interval two_pi, t;
  mpfi_const_pi(two_pi.get());
  mpfi_mul_ui(two_pi.get(), two_pi.get(), 2);
  Ends E(size_t(R.size()) * nv * 3);
  for (int b = 0; b < R.size(); ++b)
    for (int v = 0; v < nv; ++v)
      for (int k = -1; k <= 1; ++k) {
        std::array<double, 2>& e = E[(size_t(b) * nv + v) * 3 + k + 1];
        e = {R.lo(b, v), R.hi(b, v)};
        if (k == 0 || !periodic[v]) continue;
        mpfi_mul_si(t.get(), two_pi.get(), k);
        mpfi_add_d(t.get(), t.get(), R.lo(b, v));
        e[0] = t.lo_down();
        mpfi_mul_si(t.get(), two_pi.get(), k);
        mpfi_add_d(t.get(), t.get(), R.hi(b, v));
        e[1] = t.hi_up();
      }
  return E;
}

bool meets(const BoxStore& R, const Ends& E, int a, int b, int v, int k) {
  const std::array<double, 2>& e = E[(size_t(b) * R.nv() + v) * 3 + k + 1];
  return R.lo(a, v) <= e[1] && e[0] <= R.hi(a, v);
}

void expect_format_graph(const std::string& file, double eps) {
  set_working_precision(53);
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/" + file);
  AspectsConfig cfg;
  cfg.eps = eps;
  AspectsResult r = compute_aspects(m, cfg);
  std::vector<bool> periodic;
  for (const auto& v : m.vars) periodic.push_back(v.periodic);
  const BoxStore& R = r.boxes.ends();
  const int nv = R.nv();
  auto E = shifted_ends(R, periodic);
  std::set<std::pair<int, int>> want;
  for (int a = 0; a < R.size(); ++a)
    for (int b = a + 1; b < R.size(); ++b) {
      bool all = true;
      for (int v = 0; v < nv && all; ++v)
        all = meets(R, E, a, b, v, -1) || meets(R, E, a, b, v, 0) || meets(R, E, a, b, v, 1);
      if (all) want.insert({a, b});
    }
  std::set<std::pair<int, int>> got;
  for (const NeighborPair& e : neighbor_pairs(r.tree, R, periodic)) {
    ASSERT_LT(e.a, e.b);
    EXPECT_TRUE(got.insert({e.a, e.b}).second) << "pair listed twice: " << e.a << " " << e.b;
    for (int v = 0; v < nv; ++v) {
      EXPECT_TRUE(periodic[v] || e.shift(v) == 0);
      EXPECT_TRUE(meets(R, E, e.a, e.b, v, e.shift(v))) << "shift does not make the boxes meet";
    }
  }
  int missing = 0, extra = 0;
  for (const auto& p : want) missing += !got.count(p);
  for (const auto& p : got) extra += !want.count(p);
  EXPECT_EQ(missing, 0) << file << ": pairs of FORMAT.md's M missing from the solver's";
  EXPECT_EQ(extra, 0) << file << ": pairs in the solver's M that FORMAT.md's does not have";
  EXPECT_EQ(got.size(), want.size());
  EXPECT_GT(want.size(), 0u);
}

}  // namespace

TEST(NeighborhoodGraph, PrrpEqualsFormatGraph) { expect_format_graph("prrp.robot", 0.1); }

TEST(NeighborhoodGraph, RprprEqualsFormatGraph) { expect_format_graph("rprpr.robot", 0.2); }

// Periodic commands whose images cross the seam: the case that lost pairs.
TEST(NeighborhoodGraph, RrrrrEqualsFormatGraph) { expect_format_graph("rrrrr.robot", 0.5); }

// Built in blocks run in any order, on any threads, M is the same list, sorted by (a, b).
TEST(NeighborhoodGraph, SameListForAnyBlockOrder) {
  set_working_precision(53);
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rrrrr.robot");
  AspectsConfig cfg;
  cfg.eps = 0.2;
  AspectsResult r = compute_aspects(m, cfg);
  ASSERT_GT(r.boxes.size(), 3 * 2048);  // several blocks
  std::vector<bool> periodic;
  for (const auto& v : m.vars) periodic.push_back(v.periodic);
  const ForEachIndex backwards_on_two_threads = [](int n, const std::function<void(int32_t)>& body) {
    std::thread other([&] {
      for (int i = n - 1; i >= 0; i -= 2) body(i);
    });
    for (int i = n - 2; i >= 0; i -= 2) body(i);
    other.join();
  };
  std::vector<NeighborPair> p = neighbor_pairs(r.tree, r.boxes.ends(), periodic, backwards_on_two_threads);
  std::vector<NeighborPair> serial = neighbor_pairs(r.tree, r.boxes.ends(), periodic);
  ASSERT_EQ(p.size(), serial.size());
  ASSERT_EQ(p.size(), r.neighbor_count);
  for (size_t i = 0; i < p.size(); ++i) {
    ASSERT_EQ(p[i].a, serial[i].a);
    ASSERT_EQ(p[i].b, serial[i].b);
    ASSERT_EQ(p[i].shift_code, serial[i].shift_code);
    if (i > 0) {
      ASSERT_TRUE(p[i - 1].a < p[i].a || (p[i - 1].a == p[i].a && p[i - 1].b < p[i].b));
    }
  }
}

// The solver never holds M: it streams it through the separation and through the rounds
// of links. The links must be pairs of M between solution boxes, in M's order, and the
// bound and the representatives must be those of the separation run on the whole of M.
TEST(NeighborhoodGraph, StreamedMGivesTheWholeMsResults) {
  set_working_precision(53);
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rrrrr.robot");
  AspectsConfig cfg;
  cfg.eps = 0.2;
  AspectsResult r = compute_aspects(m, cfg);
  std::vector<bool> periodic;
  for (const auto& v : m.vars) periodic.push_back(v.periodic);
  std::vector<NeighborPair> M = neighbor_pairs(r.tree, r.boxes.ends(), periodic);
  ASSERT_EQ(M.size(), r.neighbor_count);
  ASSERT_GT(r.neighbors.size(), 1000u);
  ASSERT_EQ(r.certified_links.size(), r.neighbors.size());
  size_t at = 0;  // N is a subsequence of M
  for (size_t i = 0; i < r.neighbors.size(); ++i) {
    ASSERT_EQ(r.certified_links[i], int32_t(i));
    const NeighborPair& e = r.neighbors[i];
    while (at < M.size() && (M[at].a != e.a || M[at].b != e.b)) ++at;
    ASSERT_LT(at, M.size()) << "link " << i << " is not in M, or out of M's order";
    EXPECT_EQ(M[at].shift_code, e.shift_code);
    EXPECT_TRUE(r.boxes.certified(e.a) && r.boxes.certified(e.b));
    ++at;
  }
  SeparationResult whole = separate_by_signs(r.boxes.size(), int(r.factors.size()), r.boxes.sign_column(),
                                             r.boxes.certified_column(), M, &r.csnc);
  EXPECT_EQ(whole.lower_bound, 10);
  EXPECT_EQ(r.separation.lower_bound, whole.lower_bound);
  EXPECT_EQ(r.separation.per_class, whole.per_class);
  EXPECT_EQ(r.separation.representatives, whole.representatives);
}

// Issue 50: a run stopped far down leaves a tree deeper than a thread's stack. The hulls
// and the queries walk it with their own stacks (they recursed once a level: SIGSEGV).
// Ten boxes, consecutive ones touching: M is the nine pairs (b, b + 1). The top three nodes
// hold hulls (at least 8 boxes below them); the chain below, with fewer, is walked whole by
// every query.
TEST(NeighborhoodGraph, ATreeDeeperThanTheStackIsWalked) {
  set_working_precision(53);
  const DeepTree d = deep_tree(kDeepTreeLevels, LeafFate::Unexplored, 2, 1, 8);
  ASSERT_EQ(d.boxes.size(), 10);
  const std::vector<NeighborPair> M = neighbor_pairs(d.tree, d.boxes.ends(), {false, false});
  ASSERT_EQ(M.size(), 9u);
  for (int32_t b = 0; b < 9; ++b) {
    EXPECT_EQ(M[size_t(b)].a, b);
    EXPECT_EQ(M[size_t(b)].b, b + 1);
    EXPECT_EQ(M[size_t(b)].shift_code, pack_shift({0, 0}));
  }
}
