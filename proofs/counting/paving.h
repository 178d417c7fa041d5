// The bisection step shared by the pavings of a chart's U (star_test, empty_piece).
#pragma once

#include <algorithm>
#include <vector>

#include "counting/chart.h"

namespace aspects {

// Bisects z at the middle of its u-coordinate widest relative to `box`, among those wider
// than `least` times box's, pushing both halves (each keeps z's enclosure of w, which holds
// w over both). False, with nothing pushed, when every u-coordinate is that narrow.
inline bool bisect_widest_u(const Chart& chart, const Box& box, Box&& z, double least,
                            std::vector<Box>& stack) {
  int best = -1;
  double rel = 0;
  for (size_t k = 0; k < chart.u.size(); ++k) {
    const double r = z[chart.u[k]].width_up() / std::max(box[chart.u[k]].width_up(), 1e-300);
    if (r > least && r > rel) rel = r, best = int(k);
  }
  if (best < 0) return false;
  const int var = chart.u[best];
  const double m = z[var].mid();
  Box left = z, right = std::move(z);
  left[var].set_hull(left[var].lo_down(), m);
  right[var].set_hull(m, right[var].hi_up());
  stack.push_back(std::move(left));
  stack.push_back(std::move(right));
  return true;
}

}  // namespace aspects
