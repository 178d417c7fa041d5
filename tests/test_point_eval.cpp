// The DAG at a point in doubles (core/model/point_eval.h), against the interval evaluator:
// the guesses of Newton's method read these values.
#include <gtest/gtest.h>

#include <cmath>

#include "model/model.h"
#include "model/model_eval.h"

using namespace aspects;

TEST(PointEval, EquationsAndJacobiansLieInTheIntervalEnclosures) {
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rrrrr.robot");
  ModelEvaluator ev(m);
  const double v[4] = {1.25, -3.5, 0.75, 2.5};
  std::vector<double> f, fx, fq;
  ASSERT_TRUE(ev.at_point(v, f, fx, fq));
  Box b(4);
  for (int i = 0; i < 4; ++i) b[i].set_point(v[i]);
  std::vector<Interval> fi;
  IMatrix Jx, Jq;
  ASSERT_EQ(ev.equations(b, fi), EvalStatus::Defined);
  ASSERT_EQ(ev.jacobian_x(b, Jx), EvalStatus::Defined);
  ASSERT_EQ(ev.jacobian_q(b, Jq), EvalStatus::Defined);
  ASSERT_EQ(f.size(), 2u);
  ASSERT_EQ(fx.size(), 4u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(f[i], fi[i].mid(), 1e-12 * (1 + std::fabs(f[i])));
    for (int j = 0; j < 2; ++j) {
      EXPECT_NEAR(fx[i * 2 + j], Jx(i, j).mid(), 1e-12);
      EXPECT_NEAR(fq[i * 2 + j], Jq(i, j).mid(), 1e-12);
    }
  }
  // f1 = (x1 − 8 cos q1)² + (x2 − 8 sin q1)² − 25.
  EXPECT_NEAR(f[0], std::pow(1.25 - 8 * std::cos(0.75), 2) + std::pow(-3.5 - 8 * std::sin(0.75), 2) - 25,
              1e-12);
}

TEST(PointEval, UndefinedAtAPointIsFalse) {
  Model m = parse_model(
      "robot r\npose x in [-2, 2]\ncommand q in [-5, 5]\nequation q - sqrt(x) = 0\n", "r.robot");
  ModelEvaluator ev(m);
  std::vector<double> f, fx, fq;
  const double inside[2] = {0.25, 1};
  ASSERT_TRUE(ev.at_point(inside, f, fx, fq));
  EXPECT_DOUBLE_EQ(f[0], 0.5);
  EXPECT_DOUBLE_EQ(fx[0], -1.0);  // d/dx of q − sqrt(x) at 0.25
  const double outside[2] = {-1, 1};
  EXPECT_FALSE(ev.at_point(outside, f, fx, fq));
}
