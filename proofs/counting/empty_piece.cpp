#include "counting/empty_piece.h"

#include "counting/paving.h"

#include <algorithm>

namespace aspects {

EmptyVerdict prove_piece_empty(ModelEvaluator& ev, const FactorGradients& fg, const Chart& chart,
                               const Box& box, uint32_t cls, HsWorkspace& ws, long max_boxes,
                               ConstraintChecker* constraints) {
  const int n = ev.n(), p = fg.factors();
  std::vector<Interval> values, image;
  std::vector<Box> stack{box};
  long paved = 0;
  while (!stack.empty()) {
    Box z = std::move(stack.back());
    stack.pop_back();
    if (++paved > max_boxes) return EmptyVerdict::NotProved;
    // Every w(u), u in this part, lies in the intersection.
    const HsStatus hs = hansen_sengupta(ev, z, true, image, ws, false, &chart.w);
    if (hs == HsStatus::NoSolution) continue;  // no point of V in this part of the box
    if (hs == HsStatus::Ok)
      for (int j = 0; j < n; ++j) z[chart.w[j]] = image[j];
    bool cleared = false;
    if (fg.values(ev, z, values))
      for (int i = 0; i < p && !cleared; ++i)
        cleared = (cls >> i) & 1 ? values[i].hi_up() <= 0 : values[i].lo_down() >= 0;
    if (!cleared && constraints) cleared = constraints->evaluate(z) == Truth::False;
    if (cleared) continue;
    if (!bisect_widest_u(chart, box, std::move(z), 1e-6, stack)) return EmptyVerdict::NotProved;
  }
  return EmptyVerdict::Empty;
}

}  // namespace aspects
