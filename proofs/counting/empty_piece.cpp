#include "counting/empty_piece.h"

#include <algorithm>

namespace aspects {

EmptyVerdict prove_piece_empty(ModelEvaluator& ev, const FactorGradients& fg, const Chart& chart,
                               const Box& box, uint32_t cls, HsWorkspace& ws, long max_boxes) {
  const int n = ev.n(), p = fg.factors();
  std::vector<Interval> values, image;
  std::vector<Box> stack{box};
  long paved = 0;
  while (!stack.empty()) {
    Box z = std::move(stack.back());
    stack.pop_back();
    if (++paved > max_boxes) return EmptyVerdict::NotProved;
    // Every w(u), u in this part, lies in the intersection.
    if (hansen_sengupta(ev, z, true, image, ws, false, &chart.w) == HsStatus::Ok)
      for (int j = 0; j < n; ++j) z[chart.w[j]] = image[j];
    bool cleared = false;
    if (fg.values(ev, z, values))
      for (int i = 0; i < p && !cleared; ++i)
        cleared = (cls >> i) & 1 ? values[i].hi_up() <= 0 : values[i].lo_down() >= 0;
    if (cleared) continue;
    int best = -1;
    double rel = 0;
    for (int k = 0; k < n; ++k) {
      const double r = z[chart.u[k]].width_up() / std::max(box[chart.u[k]].width_up(), 1e-300);
      if (r > rel) rel = r, best = k;
    }
    if (best < 0 || rel < 1e-6) return EmptyVerdict::NotProved;
    const int var = chart.u[best];
    const double m = z[var].mid();
    Box left = z, right = std::move(z);
    left[var].set_hull(left[var].lo_down(), m);
    right[var].set_hull(m, right[var].hi_up());
    stack.push_back(std::move(left));
    stack.push_back(std::move(right));
  }
  return EmptyVerdict::Empty;
}

}  // namespace aspects
