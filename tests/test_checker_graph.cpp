// check_cert's neighbourhood graph M (certificates/checker/fast_sweep.cpp, and the trusted
// PlainSweep of bound.cpp) against a brute-force
// enumeration of every pair with the rule of certificates/FORMAT.md: a and b + 2πk meet on
// every variable for some k in {−1, 0, 1} on periodic variables, the shifted ends rounded
// outward. The sweep only proposes pairs; a missing pair could raise the certified bound,
// so the two lists must be equal. (Seen failing when the second-variable prefilter
// compared e's ends the wrong way round, and when PlainSweep left out the shifted copies.)
#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <random>
#include <utility>
#include <vector>

#include "../certificates/checker/speed.h"

namespace {

std::vector<std::pair<int, int>> brute_force(const cc::OutBoxes& R,
                                             const std::vector<bool>& periodic,
                                             const cc::Ival& two_pi) {
  std::vector<std::pair<int, int>> out;
  cc::Ival t;
  for (size_t a = 0; a < R.size(); ++a)
    for (size_t b = a + 1; b < R.size(); ++b) {
      bool meet = true;
      for (int v = 0; v < R.nv && meet; ++v) {
        const double *x = R.box(a) + 2 * v, *y = R.box(b) + 2 * v;
        meet = false;
        for (int k = -1; k <= 1 && !meet; ++k) {
          if (k && !periodic[v]) continue;
          cc::shift_by_periods(t, two_pi, k, y[0]);
          const double lo = t.lo();
          cc::shift_by_periods(t, two_pi, k, y[1]);
          meet = x[0] <= t.hi() && lo <= x[1];
        }
      }
      if (meet) out.emplace_back(int(a), int(b));
    }
  return out;
}

// 2π, enclosed at the default precision.
cc::Ival make_two_pi() {
  cc::Ival two_pi;
  cc::const_pi(two_pi);
  cc::add(two_pi, two_pi, two_pi);
  return two_pi;
}

// Boxes on a grid of cells (so that many touch), with random widths, in nv variables of
// which those in `periodic` live in [-π, π].
cc::OutBoxes random_boxes(std::mt19937& rng, int n, const std::vector<bool>& periodic,
                          int cells = 6) {
  cc::OutBoxes R;
  R.nv = int(periodic.size());
  std::uniform_int_distribution<int> cell(0, cells - 1);
  std::uniform_real_distribution<double> jitter(0.0, 0.3);
  std::vector<double> box;
  for (int i = 0; i < n; ++i) {
    box.clear();
    for (int v = 0; v < R.nv; ++v) {
      const double scale = periodic[v] ? 2 * M_PI / cells : 1.0;
      const double origin = periodic[v] ? -M_PI : 0.0;
      const int c = cell(rng);
      box.push_back(origin + scale * (c - jitter(rng)));
      box.push_back(origin + scale * (c + 1 + jitter(rng)));
    }
    R.add_box(box.data());
    R.pos.push_back(0);
    R.neg.push_back(0);
    R.solution.push_back(1);
  }
  return R;
}

TEST(CheckerGraph, SweepFindsExactlyThePairsOfTheRule) {
  const cc::Ival two_pi = make_two_pi();
  std::mt19937 rng(7);
  const std::vector<std::vector<bool>> kinds = {
      {false, false, false}, {false, false, true}, {true, false, true}, {true, true}, {true}};
  for (const auto& periodic : kinds)
    for (int trial = 0; trial < 5; ++trial) {
      cc::OutBoxes R = random_boxes(rng, 300, periodic);
      const cc::NeighbourSweep fast(R, periodic, two_pi);
      const cc::PlainSweep plain(R, periodic, two_pi);
      for (const cc::PairSweep* sweep : {static_cast<const cc::PairSweep*>(&fast),
                                         static_cast<const cc::PairSweep*>(&plain)}) {
      std::vector<std::pair<int, int>> got;
      const size_t visited = sweep->run([&](int a, int b) { got.emplace_back(a, b); });
      EXPECT_EQ(visited, got.size());
      std::sort(got.begin(), got.end());  // a pair met through two shifts comes twice
      got.erase(std::unique(got.begin(), got.end()), got.end());
      const auto want = brute_force(R, periodic, two_pi);
      std::vector<std::pair<int, int>> missing, extra;
      std::set_difference(want.begin(), want.end(), got.begin(), got.end(),
                          std::back_inserter(missing));
      std::set_difference(got.begin(), got.end(), want.begin(), want.end(),
                          std::back_inserter(extra));
      EXPECT_EQ(missing.size(), 0u);
      EXPECT_EQ(extra.size(), 0u);
      ASSERT_GT(want.size(), 300u);
      EXPECT_LT(want.size(), 300u * 299 / 2);  // not every pair: the test can tell
      }
    }
}

}  // namespace

namespace {

// Boxes spread over 60 cells, a few of them 20 cells wide: the sweep cuts the second
// variable into strips (four mean widths each) and sweeps each alone, and a pair that meets
// in several strips must come from one of them only. Still exactly the pairs of the rule.
TEST(CheckerGraph, StripsFindExactlyThePairsOfTheRule) {
  const cc::Ival two_pi = make_two_pi();
  std::mt19937 rng(5);
  const std::vector<std::vector<bool>> kinds = {{false, false}, {true, false, false}};
  for (const auto& periodic : kinds) {
    cc::OutBoxes R = random_boxes(rng, 1500, periodic, 60);
    for (int b = 0; b < 1500; b += 100) {  // wide boxes across many strips
      double* x = R.box(size_t(b)) + 2 * (R.nv - 1);
      x[1] = x[0] + 20;
    }
    std::vector<std::pair<int, int>> got;
    const cc::NeighbourSweep sweep(R, periodic, two_pi);
    sweep.run([&](int a, int b) { got.emplace_back(a, b); });
    std::sort(got.begin(), got.end());
    const size_t visited = got.size();
    got.erase(std::unique(got.begin(), got.end()), got.end());
    EXPECT_EQ(visited, got.size());  // non-periodic sweep variables: no pair twice
    EXPECT_EQ(got, brute_force(R, periodic, two_pi));
    EXPECT_GT(got.size(), periodic.size() == 2 ? 1500u : 100u) << "too few pairs to tell";
    // Shifted ends are held only for the boxes whose shifted copy meets the hull.
    size_t seam = 0;
    if (periodic[0]) {
      double hlo = 1e300, hhi = -1e300;
      for (int b = 0; b < 1500; ++b) {
        hlo = std::min(hlo, R.box(b)[0]);
        hhi = std::max(hhi, R.box(b)[1]);
      }
      for (int b = 0; b < 1500; ++b)
        seam += R.box(b)[0] + 2 * M_PI <= hhi || R.box(b)[1] - 2 * M_PI >= hlo;
      EXPECT_GT(seam, 10u);
      EXPECT_LT(seam, 150u);
    }
    EXPECT_EQ(sweep.seam_boxes(), seam);
  }
}

// Ends beyond the floats' range (the strips keep e's ends as floats rounded outward): a
// box reaching 1e39 or -1e300 still meets exactly the boxes of the rule.
TEST(CheckerGraph, EndsBeyondTheFloatsRange) {
  const cc::Ival two_pi = make_two_pi();
  std::mt19937 rng(9);
  const std::vector<bool> periodic = {false, false};
  cc::OutBoxes R = random_boxes(rng, 600, periodic, 60);
  for (int v = 0; v < 2; ++v)
    for (int b = v; b < 600; b += 50) {
      double* x = R.box(size_t(b)) + 2 * v;
      if (b % 100 < 50) x[1] = 1e39;
      else x[0] = -1e300;
    }
  std::vector<std::pair<int, int>> got;
  const cc::NeighbourSweep sweep(R, periodic, two_pi);
  sweep.run([&](int a, int b) { got.emplace_back(a, b); });
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, brute_force(R, periodic, two_pi));
  EXPECT_GT(got.size(), 600u);
}

// A third variable g, periodic, whose ends the items hold: boxes on a 10 × 10 grid of the
// first two variables, each touching one seam of g, [-π, -π + 1] or [π - 1, π] as doubles.
// A pair across the seam meets only through b_g − 2π, its upper end rounded outward up to
// exactly a_g's lower end: the prefilter on g must keep such a contact. (Seen failing with
// the shifts left out of the prefilter, and with a slack of −1e-3 instead of +1e-9.)
TEST(CheckerGraph, ThirdVariableKeepsContactsAcrossTheSeam) {
  const cc::Ival two_pi = make_two_pi();
  const std::vector<bool> periodic = {false, false, true};
  cc::OutBoxes R;
  R.nv = 3;
  for (int i = 0; i < 200; ++i) {
    const double x = i % 10, y = i / 10 % 10;
    const double g0 = i % 2 ? M_PI - 1 : -M_PI, g1 = i % 2 ? M_PI : -M_PI + 1;
    const double box[6] = {x, x + 1, y, y + 1, g0, g1};
    R.add_box(box);
    R.pos.push_back(0);
    R.neg.push_back(0);
    R.solution.push_back(1);
  }
  const cc::NeighbourSweep sweep(R, periodic, two_pi);
  std::vector<std::pair<int, int>> got;
  sweep.run([&](int a, int b) { got.emplace_back(a, b); });
  std::sort(got.begin(), got.end());
  got.erase(std::unique(got.begin(), got.end()), got.end());
  const auto want = brute_force(R, periodic, two_pi);
  EXPECT_EQ(got, want);
  // Boxes 0 (x, y = 0, 0; g at -π) and 1 (x = 1; g at π) meet across the seam only.
  EXPECT_TRUE(std::binary_search(want.begin(), want.end(), std::make_pair(0, 1)));
}

// Bound (11) by the book: per sign class, a union-find over the brute-force pairs.
long brute_force_bound(const cc::OutBoxes& R, const std::vector<std::pair<int, int>>& M,
                       uint32_t full) {
  std::vector<uint32_t> classes;
  for (size_t b = 0; b < R.size(); ++b)
    if (R.solution[b] && ((R.pos[b] | R.neg[b]) & full) == full) classes.push_back(R.pos[b] & full);
  std::sort(classes.begin(), classes.end());
  classes.erase(std::unique(classes.begin(), classes.end()), classes.end());
  long total = 0;
  for (uint32_t s : classes) {
    auto compatible = [&](int b) { return !(R.neg[b] & s) && !(R.pos[b] & ~s & full); };
    cc::UnionFind uf;
    uf.reset(R.size());
    for (const auto& e : M)
      if (compatible(e.first) && compatible(e.second)) uf.unite(e.first, e.second);
    std::vector<int> roots;
    for (size_t b = 0; b < R.size(); ++b)
      if (R.solution[b] && (R.pos[b] & full) == s && (R.neg[b] & full) == (~s & full))
        roots.push_back(uf.find(int(b)));
    std::sort(roots.begin(), roots.end());
    total += long(std::unique(roots.begin(), roots.end()) - roots.begin());
  }
  return total;
}

}  // namespace

// The streamed bound (one sweep of M per group of at most 32 classes, a union-find per
// class) equals the bound by the book, with more than 32 classes so that several groups
// run, and with some factors left out of `use`.
TEST(CheckerGraph, StreamedBoundEqualsTheBoundByTheBook) {
  const cc::Ival two_pi = make_two_pi();
  std::mt19937 rng(11);
  const std::vector<bool> periodic = {false, true, false};
  std::uniform_int_distribution<int> sign(0, 5);
  for (int trial = 0; trial < 4; ++trial) {
    cc::OutBoxes R = random_boxes(rng, 400, periodic);
    for (size_t b = 0; b < R.size(); ++b) {
      R.pos[b] = R.neg[b] = 0;
      for (int i = 0; i < 7; ++i) {  // 7 factors: up to 128 classes
        const int s = sign(rng);     // mostly proved signs, some unproved
        if (s < 3) R.pos[b] |= 1u << i;
        else if (s < 5) R.neg[b] |= 1u << i;
      }
      R.solution[b] = sign(rng) != 0;
    }
    const auto M = brute_force(R, periodic, two_pi);
    const cc::NeighbourSweep sweep(R, periodic, two_pi);
    size_t classes = 0;
    for (uint32_t use : {0x7fu, 0x1fu, 0x3u}) {
      size_t pairs = 0;
      const long want = brute_force_bound(R, M, use);
      EXPECT_EQ(cc::lower_bound(R, sweep, use, SIZE_MAX, &pairs), want) << "use " << use;
      EXPECT_GE(pairs, M.size());  // a pair met through two shifts is visited twice
      if (use == 0x7fu) {
        std::vector<uint32_t> s;
        for (size_t b = 0; b < R.size(); ++b)
          if (R.solution[b] && ((R.pos[b] | R.neg[b]) & use) == use) s.push_back(R.pos[b]);
        std::sort(s.begin(), s.end());
        classes = size_t(std::unique(s.begin(), s.end()) - s.begin());
      }
      EXPECT_GT(want, 0);
    }
    EXPECT_GT(classes, 32u);  // several groups of classes ran
  }
}

// Beyond the pair limit the sweep stops with std::length_error.
TEST(CheckerGraph, PairLimitStopsTheSweep) {
  const cc::Ival two_pi = make_two_pi();
  std::mt19937 rng(3);
  cc::OutBoxes R = random_boxes(rng, 300, {false, false});
  const cc::NeighbourSweep sweep(R, {false, false}, two_pi);
  const size_t all = sweep.run([](int, int) {});
  ASSERT_GT(all, 10u);
  EXPECT_EQ(sweep.run([](int, int) {}, all), all);
  EXPECT_THROW(sweep.run([](int, int) {}, all - 1), std::length_error);
  EXPECT_THROW(cc::lower_bound(R, sweep, 0, all - 1), std::length_error);
}

// The strips swept on several threads: the same pairs, each as often, as on one thread;
// the same bound; the pair limit and a visitor's exception still end the sweep.
TEST(CheckerGraph, ThreadsSweepTheSamePairs) {
  const cc::Ival two_pi = make_two_pi();
  std::mt19937 rng(13);
  const std::vector<bool> periodic = {true, false};
  cc::OutBoxes R = random_boxes(rng, 2000, periodic, 60);
  for (size_t b = 0; b < R.size(); ++b) {  // two sign classes
    R.pos[b] = b % 3 ? 1 : 0;
    R.neg[b] = b % 3 ? 0 : 1;
  }
  const cc::NeighbourSweep sweep(R, periodic, two_pi);
  std::vector<std::pair<int, int>> one;
  const size_t all = sweep.run([&](int a, int b) { one.emplace_back(a, b); });
  std::sort(one.begin(), one.end());
  ASSERT_GT(all, 2000u);
  const long bound = cc::lower_bound(R, sweep, 1, SIZE_MAX, nullptr, 1);
  ASSERT_GT(bound, 1);
  for (int threads : {2, 3, 8}) {
    std::vector<std::pair<int, int>> got;
    EXPECT_EQ(sweep.run([&](int a, int b) { got.emplace_back(a, b); }, SIZE_MAX, threads), all);
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, one) << threads << " threads";
    EXPECT_EQ(cc::lower_bound(R, sweep, 1, SIZE_MAX, nullptr, threads), bound);
    EXPECT_EQ(sweep.run([](int, int) {}, all, threads), all);
    EXPECT_THROW(sweep.run([](int, int) {}, all - 1, threads), std::length_error);
    EXPECT_THROW(cc::lower_bound(R, sweep, 1, all - 1, nullptr, threads), std::length_error);
    size_t seen = 0;
    EXPECT_THROW(sweep.run(
                     [&](int, int) {
                       if (++seen == all / 2) throw std::runtime_error("visitor");
                     },
                     SIZE_MAX, threads),
                 std::runtime_error);
  }
}
