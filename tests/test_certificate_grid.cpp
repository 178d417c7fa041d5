// The grids of certificate format 3 (proofs/certificate_grid.h): what the solver snaps to
// is what the writer can code, and what it codes is what a checker decodes with FORMAT.md's
// formula, fma(z, (b − a)·2^-G, r). Random intervals of many magnitudes, a fixed seed.
//
// Seen failing (each break made in proofs/certificate_grid.h, then reverted):
//  - snap() without its correction loops (z from the rounded quotient alone): next to a grid
//    value it misses the nearest one (SnapIsOnTheGridAndOnItsSide);
//  - value() as r + z·u without fma: codes that do not decode to the value they code
//    (CodeDecodesAsTheCheckerDoes).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "certificate_grid.h"

namespace aspects {
namespace {

// FORMAT.md's decoding, written out as a checker does it.
double decode(double a, double b, bool upper, int64_t z, int bits) {
  return std::fma(double(z), std::ldexp(b - a, -bits), upper ? b : a);
}

struct Case {
  double a, b, x;
};

Case random_case(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  const double scale = std::ldexp(1.0, int(unit(rng) * 40) - 20);
  const double a = (unit(rng) - 0.5) * scale;
  const double b = a + unit(rng) * scale * std::ldexp(1.0, -int(unit(rng) * 20));
  return {a, b, a + unit(rng) * (b - a)};
}

TEST(CertificateGrid, SnapIsOnTheGridAndOnItsSide) {
  std::mt19937_64 rng(31);
  int usable = 0;
  for (int i = 0; i < 200000; ++i) {
    const Case c = random_case(rng);
    for (int bits : {grid::kBits, grid::kContractionBits}) {
      const double u = grid::step(c.a, c.b, bits);
      if (u == 0) continue;
      ++usable;
      for (bool upper : {false, true}) {
        const double r = upper ? c.b : c.a;
        // x, and the doubles next to a grid value near it, where the rounded quotient
        // (x − r)/u can fall on the wrong side of an integer.
        const double g = grid::snap(c.x, r, u, false);
        for (double x : {c.x, g, std::nextafter(g, -INFINITY), std::nextafter(g, INFINITY)}) {
          const double down = grid::snap(x, r, u, false), up = grid::snap(x, r, u, true);
          ASSERT_LE(down, x);
          ASSERT_GE(up, x);
          int64_t zd, zu;
          ASSERT_TRUE(grid::code(down, r, u, zd));
          ASSERT_TRUE(grid::code(up, r, u, zu));
          // The nearest grid values: nothing of the grid lies strictly between them and x.
          ASSERT_GT(grid::value(r, u, zd + 1), x);
          ASSERT_LT(grid::value(r, u, zu - 1), x);
          // Inside [a, b] the codes are at most 2^bits steps from their end.
          ASSERT_LE(std::llabs(zd), (int64_t(1) << bits) + 1);
        }
      }
    }
  }
  EXPECT_GT(usable, 300000);  // most random intervals have a grid
}

TEST(CertificateGrid, CodeDecodesAsTheCheckerDoes) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 200000; ++i) {
    const Case c = random_case(rng);
    const double u = grid::step(c.a, c.b);
    if (u == 0) continue;
    const double on = grid::snap(c.x, c.a, u, true);
    int64_t z;
    ASSERT_TRUE(grid::code(on, c.a, u, z));
    ASSERT_EQ(decode(c.a, c.b, false, z, grid::kBits), on);
    const double hi_side = grid::snap(c.x, c.b, u, false);
    ASSERT_TRUE(grid::code(hi_side, c.b, u, z));
    ASSERT_LE(z, 0);
    ASSERT_EQ(decode(c.a, c.b, true, z, grid::kBits), hi_side);
  }
}

TEST(CertificateGrid, OffTheGridIsNotCoded) {
  // x strictly between two neighbouring grid values has no code: the writer stores it raw.
  const double a = 1.0, b = 2.0, u = grid::step(a, b);
  ASSERT_EQ(u, std::ldexp(1.0, -16));
  int64_t z;
  EXPECT_TRUE(grid::code(1.5, a, u, z));
  EXPECT_EQ(z, 1 << 15);
  EXPECT_FALSE(grid::code(1.5 + std::ldexp(1.0, -20), a, u, z));
  EXPECT_FALSE(grid::code(NAN, a, u, z));
}

TEST(CertificateGrid, TheReferenceEndIsCodeZeroOnAnyGrid) {
  int64_t z = 5;
  // A point interval has no grid, but its one value is z = 0 (fma(0, 0, a) = a).
  EXPECT_EQ(grid::step(0.0, 0.0), 0);
  EXPECT_TRUE(grid::code(0.0, 0.0, 0.0, z));
  EXPECT_EQ(z, 0);
  EXPECT_EQ(decode(0.0, 0.0, false, 0, grid::kBits), 0.0);
  EXPECT_FALSE(grid::code(1e-300, 0.0, 0.0, z));
}

TEST(CertificateGrid, TooFineAGridIsNotUsed) {
  // [1e10, 1e10 + 1e-3]: a step of 1.5e-8 is below the doubles' spacing there (1.9e-6).
  EXPECT_EQ(grid::step(1e10, 1e10 + 1e-3), 0);
  const double x = 1e10 + 2e-4;
  EXPECT_EQ(grid::snap(x, 1e10, 0, false), x);  // no grid: the value stays as it is
  EXPECT_GT(grid::step(-1, 1), 0);
  EXPECT_EQ(grid::step(0, INFINITY), 0);
}

}  // namespace
}  // namespace aspects
