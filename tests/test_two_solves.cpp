// Two solves at once in one process, one of them MPFI only: each run's
// evaluators compute as its own configuration asks, and each result is a single run's.
// Deliberate break that made it fail: the arithmetic read from one process-wide switch
// that each run sets as it starts (the old `set_double_fast_path`): both runs then
// computed as the run that started last asked, and the other's expectations failed.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "generalized_aspects.h"

using namespace aspects;

namespace {

struct SolveRun {
  AspectsResult r;
  std::atomic<long> in_doubles{0}, in_mpfi{0};
};

// Solves RPRPR at eps 0.1 on 2 threads with `arithmetic`. When `together` is set, the
// first evaluator of the run waits there until the other run made its first one too, so
// that the two runs overlap.
void solve(Arithmetic arithmetic, SolveRun& run, std::atomic<int>* together) {
  set_working_precision(53);
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rprpr.robot");
  AspectsConfig cfg;
  cfg.eps = 0.1;
  cfg.threads = 2;
  cfg.arithmetic = arithmetic;
  std::atomic<bool> waited{false};
  cfg.evaluator_made = [&](Arithmetic a) {
    ++(a == Arithmetic::DoublesFirst ? run.in_doubles : run.in_mpfi);
    if (together && !waited.exchange(true)) {
      ++*together;
      const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
      while (*together < 2 && std::chrono::steady_clock::now() < until)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  };
  run.r = compute_aspects(m, cfg);
}

void expect_same_result(const AspectsResult& a, const AspectsResult& b) {
  EXPECT_EQ(a.solutions, b.solutions);
  EXPECT_EQ(a.undecided, b.undecided);
  EXPECT_EQ(a.discarded, b.discarded);
  EXPECT_EQ(a.boxes.size(), b.boxes.size());
  EXPECT_EQ(a.certified_links, b.certified_links);
  EXPECT_EQ(a.csnc_sizes, b.csnc_sizes);
  EXPECT_EQ(a.separation.lower_bound, b.separation.lower_bound);
}

}  // namespace

TEST(TwoSolves, EachComputesAsItsConfigurationAsks) {
  SolveRun alone;
  solve(Arithmetic::DoublesFirst, alone, nullptr);
  EXPECT_GT(alone.in_doubles, 0);
  EXPECT_EQ(alone.in_mpfi, 0);

  SolveRun doubles, mpfi;
  std::atomic<int> together{0};
  // MPFR caches constants (π) per thread: a thread of our own frees them before it ends, or
  // LeakSanitizer reports them.
  std::thread a([&] {
    solve(Arithmetic::DoublesFirst, doubles, &together);
    mpfr_free_cache();
  });
  std::thread b([&] {
    solve(Arithmetic::MpfiOnly, mpfi, &together);
    mpfr_free_cache();
  });
  a.join();
  b.join();
  EXPECT_EQ(together, 2);  // they overlapped
  EXPECT_GT(doubles.in_doubles, 0);
  EXPECT_EQ(doubles.in_mpfi, 0);
  EXPECT_GT(mpfi.in_mpfi, 0);
  EXPECT_EQ(mpfi.in_doubles, 0);
  // Both arithmetics give the same ends, hence a single run's result.
  expect_same_result(doubles.r, alone.r);
  expect_same_result(mpfi.r, alone.r);
  EXPECT_EQ(alone.r.solutions, 1428);  // as `aspects solve robots/rprpr.robot --eps 0.1`
  EXPECT_EQ(alone.r.undecided, 712);
  EXPECT_EQ(alone.r.csnc_sizes.size(), 2u);
  EXPECT_EQ(alone.r.separation.lower_bound, 2);
}
