// The grid of certificate format 3 (certificates/FORMAT.md, "Format 3"): a recorded end
// is coded as a small integer z, meaning fma(z, u, r) with r an end of a reference interval
// [a, b] the checker already knows (the cell, Q~, a linked box) and u = (b − a)·2^-16. A
// value off the grid is recorded as its 8 bytes instead, so any value can be written; the
// solver puts its values on the grid (outward, where a claim must only get weaker) so
// that nearly all of them take one to three bytes.
//
// fma rounds once, so the writer and any checker get the same double on any machine.
#pragma once

#include <cmath>
#include <cstdint>

namespace aspects::grid {

constexpr int kBits = 16;
// Contractions are coded on a coarser grid: each is weakened by at most 2^-10 of the
// cell's width, and its ends take one or two bytes instead of two or three.
constexpr int kContractionBits = 10;

// The step of the grid of [a, b]; 0 when it has no usable grid: empty, infinite, or so
// narrow beside its magnitude that neighbouring grid values could round to one double.
inline double step(double a, double b, int bits = kBits) {
  const double u = std::ldexp(b - a, -bits);
  const bool fine = u >= 0x1p-1000 && u >= (std::fabs(a) + std::fabs(b)) * 0x1p-48;
  return std::isfinite(u) && fine ? u : 0;
}

inline double value(double r, double u, int64_t z) { return std::fma(double(z), u, r); }

// The z with value(r, u, z) == x, if there is one of magnitude below 2^40. x == r is
// z = 0 on any grid, also that of a point [a, a] (a checker computes fma(0, u, r) = r).
inline bool code(double x, double r, double u, int64_t& z) {
  if (x == r) return z = 0, true;
  if (u == 0 || !std::isfinite(x)) return false;
  const double q = (x - r) / u;
  if (!(std::fabs(q) < 0x1p40)) return false;
  const int64_t z0 = int64_t(std::llround(q));
  for (int64_t d : {0, -1, 1})
    if (value(r, u, z0 + d) == x) return z = z0 + d, true;
  return false;
}

// The largest grid value <= x (down) or the smallest >= x (up); x itself when there is no
// grid or x is too far from r.
inline double snap(double x, double r, double u, bool up) {
  if (u == 0 || !std::isfinite(x)) return x;
  const double q = (x - r) / u;
  if (!(std::fabs(q) < 0x1p40)) return x;
  int64_t z = int64_t(up ? std::ceil(q) : std::floor(q));
  // The division is rounded: step to the first value on the right side.
  if (up) {
    while (value(r, u, z) < x) ++z;
    while (value(r, u, z - 1) >= x) --z;
  } else {
    while (value(r, u, z) > x) --z;
    while (value(r, u, z + 1) <= x) ++z;
  }
  return value(r, u, z);
}

}  // namespace aspects::grid
