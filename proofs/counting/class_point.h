// A certified point of W_s in a box: a point of the solution set V in the box where every
// factor has its sign s_i strictly. Chosen in doubles (a grid of the box's u-part, Newton
// for w), then proved: iteration (9) at the u-point gives a unique w in an enclosure that
// lies in the box's w-part, and on (u, enclosure) each factor's enclosure has sign s_i.
// A piece's star centre is one (its piece is nonempty); a point in the inner intersection of
// two boxes joins their pieces of class s (an adjacency "joined").
#pragma once

#include <cstdint>
#include <vector>

#include "counting/chart.h"
#include "counting/factor_gradients.h"

namespace aspects {

struct ClassPoint {
  std::vector<int> u_vars, w_vars;  // the chart's variables
  std::vector<double> u;            // the u-point, n doubles (u_vars order)
  std::vector<Interval> w;          // the enclosure of its unique w (w_vars order)
};

enum class PointVerdict : uint8_t { Found, NotFound };

// w_vars: the chart's w (the unknowns). cls: bit i set when factor i is positive.
// per_axis: grid points per u-axis.
PointVerdict find_class_point(ModelEvaluator& ev, const FactorGradients& fg, const Box& box,
                              const std::vector<int>& w_vars, uint32_t cls, HsWorkspace& ws,
                              ClassPoint& out, int per_axis = 5);

}  // namespace aspects
