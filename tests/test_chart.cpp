// Charts of the counting (proofs/counting/chart.h): which are tried on a box, and what a
// proved one claims.
#include <gtest/gtest.h>

#include "counting/chart.h"
#include "model/model.h"

using namespace aspects;

namespace {

Box box_of(const std::vector<double>& lo, const std::vector<double>& hi) {
  Box b(lo.size());
  for (size_t v = 0; v < lo.size(); ++v) b[v].set_hull(lo[v], hi[v]);
  return b;
}

}  // namespace

// A box of the RRRRR first cover (ε 0.1) near the serial singularity of leg 1 (x − e1 nearly
// orthogonal to the crank): q1 is nearly a fold of x, so w = (x1, q2) over u = (x2, q1) fits
// the box, while the pose chart fails (∂f1/∂q1 ≈ 0), the command chart too (the forward
// kinematics over the box's q1 spans three units of x), and the charts ranked by the
// conditioning of their columns put q1 in w. The candidates tried must reach one that holds.
TEST(Chart, NearASerialSingularityAMixedChartIsTried) {
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rrrrr.robot");
  ModelEvaluator ev(m);
  HsWorkspace ws;
  const Box b = box_of({-2.88171, -1.15937, -2.9527, 2.67342}, {-2.82611, -1.10416, -2.85576, 2.72539});
  const std::vector<double> scale{40, 40, 2 * M_PI, 2 * M_PI};
  Chart chart;
  EXPECT_NE(prove_chart(ev, b, m.command, ws, chart), ChartVerdict::Proved);
  EXPECT_NE(prove_chart(ev, b, m.pose, ws, chart), ChartVerdict::Proved);
  std::vector<int> proved;
  for (const std::vector<int>& w : chart_candidates(ev, b, scale))
    if (prove_chart(ev, b, w, ws, chart) == ChartVerdict::Proved) {
      proved = w;
      break;
    }
  ASSERT_EQ(proved, (std::vector<int>{0, 3}));
  // The graph over the box's (x2, q1) stays near the box: x1 within 0.2, q2 within 0.06.
  EXPECT_EQ(chart.u, (std::vector<int>{1, 2}));
  EXPECT_LT(chart.w_range[0].width_up(), 0.2);
  EXPECT_LT(chart.w_range[1].width_up(), 0.06);
  EXPECT_TRUE(chart.w_range[0].contains(Interval(-2.8)));
  EXPECT_TRUE(chart.w_range[1].contains(Interval(2.7)));
}

// A box of a refined RRRRR cover, 0.008 wide in the pose, whose q1 the contraction left 0.4
// wide (x1 sin q1 − x2 cos q1 is evaluated as a difference of products that cancel): no
// chart holds, and cutting the pose again leaves q1 as wide. The cut is q1.
TEST(Chart, AWideCommandTheContractionLeftIsCut) {
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rrrrr.robot");
  ModelEvaluator ev(m);
  HsWorkspace ws;
  const Box b = box_of({2.97266, -3.06082, -0.441412, 2.11117}, {2.98096, -3.05303, -0.0449556, 2.16794});
  const std::vector<double> scale{40, 40, 2 * M_PI, 2 * M_PI};
  Chart chart;
  for (const std::vector<int>& w : chart_candidates(ev, b, scale, 6))
    EXPECT_NE(prove_chart(ev, b, w, ws, chart), ChartVerdict::Proved);
  EXPECT_EQ(chart_split_variable(ev, b, scale), 2);
}
