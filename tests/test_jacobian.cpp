// Interval Jacobians: for every robot of robots/, Fx and Fq evaluated on a box around a
// point contain the central finite difference of the equations at that point, computed
// in MPFR at 256 bits with step 1e-30 (it differs from the derivative by O(h^2) ~ 1e-60,
// far below any interval width used here). The same check for the derivative rule of
// every DAG operation, and the symbolic structure of the Jacobians.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "model/eval.h"
#include "model/expr.h"
#include "model/model.h"
#include "model/model_eval.h"
#include "model/model_info.h"
#include "robot_refs.h"
#include "test_util.h"

using namespace aspects;
using aspects_test::interval_str;
using aspects_test::Point;
using aspects_test::R;
using aspects_test::RobotRef;

namespace {

// Step h = 2^-100 (~7.9e-31): a power of two, so p +- h is exact at 256 bits for the
// double points used here, and the difference quotient of a linear function is exact.
R step() {
  R h;
  mpfr_set_ui_2exp(h.get(), 1, -100, MPFR_RNDN);
  return h;
}

// d f_i / d var_j at p, central difference, for all i.
std::vector<R> central_difference(const RobotRef& ref, const Point& p, size_t j) {
  R h = step();
  Point plus = p, minus = p;
  plus[j] = p[j] + h;
  minus[j] = p[j] - h;
  std::vector<R> fp = ref.f(plus), fm = ref.f(minus), d;
  for (size_t i = 0; i < fp.size(); ++i) d.push_back((fp[i] - fm[i]) / (R(2) * h));
  return d;
}

bool is_fixed(const Interval& d) { return mpfr_equal_p(&d.get()->left, &d.get()->right); }

class JacobianRobot : public ::testing::TestWithParam<RobotRef> {
 protected:
  void SetUp() override {
    set_working_precision(53);
    aspects_test::ref_prec() = 256;
  }
};

TEST_P(JacobianRobot, ContainsFiniteDifferences) {
  const RobotRef& ref = GetParam();
  Model m = load_model(ref.path());
  ASSERT_EQ(m.var_names(), ref.vars);
  const int n = m.n(), nv = int(m.vars.size());
  ASSERT_EQ(int(m.pose.size()), n);
  ASSERT_EQ(int(m.command.size()), n);
  ModelEvaluator me(m);
  const Box domain = m.initial_box();
  std::mt19937 g(99u + unsigned(ref.file.size()) * 13u);
  IMatrix jx, jq;
  long checked = 0;

  // Checks every entry of Fx, Fq (already evaluated on `box`) against FD at p.
  auto check_at = [&](const Point& p, const Box& box, const char* what) {
    for (int j = 0; j < nv; ++j) {
      std::vector<R> d = central_difference(ref, p, size_t(j));
      for (int i = 0; i < n; ++i) {
        bool pose = m.vars[j].kind == VarKind::Pose;
        const std::vector<int>& cols = pose ? m.pose : m.command;
        int col = int(std::find(cols.begin(), cols.end(), j) - cols.begin());
        const Interval& e = pose ? jx(i, col) : jq(i, col);
        int node = (pose ? m.fx : m.fq)[size_t(i) * n + col];
        ++checked;
        EXPECT_TRUE(aspects_test::interval_contains(e, d[size_t(i)]))
            << ref.name << " " << what << ": d eq" << i + 1 << " / d " << m.vars[j].name
            << " = " << d[size_t(i)].str(25) << " (finite difference) not in " << interval_str(e, 25)
            << "\npoint:" << [&] {
                 std::string s;
                 for (int k = 0; k < nv; ++k) s += " " + m.vars[k].name + "=" + p[k].str(20);
                 return s;
               }() << "\nbox[" << m.vars[j].name << "] = " << interval_str(box[j], 20);
        // A structurally zero entry must really be zero (the equation ignores var j).
        if (node == m.dag.zero()) {
          EXPECT_TRUE(mpfr_zero_p(d[size_t(i)].get()))
              << ref.name << ": d eq" << i + 1 << " / d " << m.vars[j].name
              << " is structurally zero but the finite difference is " << d[size_t(i)].str();
        }
      }
    }
  };

  for (int k = 0; k < 60; ++k) {
    Point p;
    for (int j = 0; j < nv; ++j) {
      double lo = domain[j].lo_down(), hi = domain[j].hi_up();
      p.push_back(is_fixed(domain[j]) ? R(lo) : R(aspects_test::uniform(g, lo, hi)));
    }
    for (double w : {1e-12, 1e-6, 1e-2, 0.5}) {
      Box box;
      for (int j = 0; j < nv; ++j) box.push_back(aspects_test::ball(p[j], w));
      ASSERT_EQ(me.jacobian_x(box, jx), EvalStatus::Defined);
      ASSERT_EQ(me.jacobian_q(box, jq), EvalStatus::Defined);
      ASSERT_EQ(jx.rows(), n);
      ASSERT_EQ(jx.cols(), n);
      ASSERT_EQ(jq.rows(), n);
      ASSERT_EQ(jq.cols(), n);
      check_at(p, box, w == 1e-12 ? "near-point box" : "box");
      if (w >= 1e-2) {
        // Other points of the same box.
        for (int s = 0; s < 3; ++s) {
          Point p2;
          for (int j = 0; j < nv; ++j)
            p2.push_back(R(aspects_test::uniform(g, box[j].lo_down(), box[j].hi_up())));
          check_at(p2, box, "box (inner point)");
        }
      }
    }
    // The fixed pose variable of 3-RRR* on its exact (degenerate) domain.
    bool any_fixed = false;
    Box box;
    for (int j = 0; j < nv; ++j) {
      any_fixed = any_fixed || is_fixed(domain[j]);
      box.push_back(is_fixed(domain[j]) ? domain[j] : aspects_test::ball(p[j], 1e-12));
    }
    if (any_fixed) {
      ASSERT_EQ(me.jacobian_x(box, jx), EvalStatus::Defined);
      ASSERT_EQ(me.jacobian_q(box, jq), EvalStatus::Defined);
      check_at(p, box, "fixed-variable box");
    }
  }
  EXPECT_GT(checked, 60 * n * nv);
}

// On the points of the constraint surface as well (where the solver works).
TEST_P(JacobianRobot, ContainsFiniteDifferencesOnTheSurface) {
  const RobotRef& ref = GetParam();
  Model m = load_model(ref.path());
  const int n = m.n(), nv = int(m.vars.size());
  ModelEvaluator me(m);
  std::mt19937 g(7);
  IMatrix jx, jq;
  for (int k = 0; k < 40; ++k) {
    Point p = ref.solution(g);
    Box box;
    for (int j = 0; j < nv; ++j) box.push_back(aspects_test::ball(p[j], 1e-12));
    ASSERT_EQ(me.jacobian_x(box, jx), EvalStatus::Defined);
    ASSERT_EQ(me.jacobian_q(box, jq), EvalStatus::Defined);
    for (int j = 0; j < nv; ++j) {
      std::vector<R> d = central_difference(ref, p, size_t(j));
      bool pose = m.vars[j].kind == VarKind::Pose;
      const std::vector<int>& cols = pose ? m.pose : m.command;
      int col = int(std::find(cols.begin(), cols.end(), j) - cols.begin());
      for (int i = 0; i < n; ++i) {
        const Interval& e = pose ? jx(i, col) : jq(i, col);
        EXPECT_TRUE(aspects_test::interval_contains(e, d[size_t(i)]))
            << ref.name << ": d eq" << i + 1 << " / d " << m.vars[j].name << " = "
            << d[size_t(i)].str(25) << " not in " << interval_str(e, 25);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Robots, JacobianRobot, ::testing::ValuesIn(aspects_test::robot_refs()),
                         [](const ::testing::TestParamInfo<RobotRef>& info) {
                           return "r" + info.param.file.substr(0, info.param.file.find('.'));
                         });

// ----------------------------------------------------------------- structure

Model robot(const char* file) { return load_model(std::string(ASPECTS_ROBOTS_DIR) + "/" + file); }

TEST(JacobianStructure, RrrrrFqIsDiagonalFxIsFull) {
  set_working_precision(53);
  Model m = robot("rrrrr.robot");
  ASSERT_EQ(m.n(), 2);
  EXPECT_EQ(structural_shape(m.dag, m.fq, 2), MatrixShape::Diagonal);
  EXPECT_EQ(structural_shape(m.dag, m.fx, 2), MatrixShape::Full);
  EXPECT_EQ(m.fq[1], m.dag.zero());
  EXPECT_EQ(m.fq[2], m.dag.zero());
  EXPECT_NE(m.fq[0], m.dag.zero());
  EXPECT_NE(m.fq[3], m.dag.zero());
}

TEST(JacobianStructure, PrrpHasOneByOneMatrices) {
  set_working_precision(53);
  Model m = robot("prrp.robot");
  ASSERT_EQ(m.n(), 1);
  EXPECT_EQ(m.fx.size(), 1u);
  EXPECT_EQ(m.fq.size(), 1u);
  ModelEvaluator me(m);
  IMatrix jx, jq;
  Box box{Interval(0.6), Interval(0.8)};
  ASSERT_EQ(me.jacobian_x(box, jx), EvalStatus::Defined);
  ASSERT_EQ(me.jacobian_q(box, jq), EvalStatus::Defined);
  EXPECT_EQ(jx.rows(), 1);
  EXPECT_EQ(jx.cols(), 1);
  EXPECT_EQ(jq.rows(), 1);
  EXPECT_EQ(jq.cols(), 1);
  // d/dx (x - 0)^2 = 2x = 1.2 exactly for the double 0.6 (a point: the DAG adds 2*x).
  EXPECT_TRUE(jx(0, 0).contains(2 * 0.6)) << interval_str(jx(0, 0));
  EXPECT_TRUE(jq(0, 0).contains(2 * 0.8)) << interval_str(jq(0, 0));
  EXPECT_LE(jx(0, 0).width_up(), 1e-15) << interval_str(jx(0, 0));
  EXPECT_EQ(structural_shape(m.dag, m.fx, 1), MatrixShape::Diagonal);
}

TEST(JacobianStructure, ThreeRrrStarFxHasAColumnForTheFixedOrientation) {
  set_working_precision(53);
  Model m = robot("3rrr_star.robot");
  ASSERT_EQ(m.n(), 3);
  ASSERT_EQ(m.pose.size(), 3u);
  EXPECT_EQ(m.vars[m.pose[2]].name, "x3");
  EXPECT_EQ(m.fx.size(), 9u);
  EXPECT_EQ(m.fx[0 * 3 + 2], m.dag.zero()) << "eq1 does not involve x3";
  EXPECT_NE(m.fx[1 * 3 + 2], m.dag.zero()) << "eq2 involves x3";
  EXPECT_NE(m.fx[2 * 3 + 2], m.dag.zero()) << "eq3 involves x3";
  EXPECT_EQ(structural_shape(m.dag, m.fx, 3), MatrixShape::Full);
  EXPECT_EQ(structural_shape(m.dag, m.fq, 3), MatrixShape::Diagonal);
  ModelEvaluator me(m);
  IMatrix jx;
  Box box = m.initial_box();
  me.jacobian_x(box, jx);
  EXPECT_EQ(jx.rows(), 3);
  EXPECT_EQ(jx.cols(), 3);
  EXPECT_EQ(jx(0, 2).lo_down(), 0.0);
  EXPECT_EQ(jx(0, 2).hi_up(), 0.0);
}

TEST(JacobianStructure, ShapesOfAllRobots) {
  set_working_precision(53);
  struct Want {
    const char* file;
    int n;
    MatrixShape fx, fq;
  } wants[] = {
      {"prrp.robot", 1, MatrixShape::Diagonal, MatrixShape::Diagonal},
      {"rprpr.robot", 2, MatrixShape::Full, MatrixShape::Diagonal},
      {"rrrrr.robot", 2, MatrixShape::Full, MatrixShape::Diagonal},
      {"3rpr.robot", 3, MatrixShape::Full, MatrixShape::Diagonal},
      {"3rrr_star.robot", 3, MatrixShape::Full, MatrixShape::Diagonal},
  };
  for (const Want& w : wants) {
    SCOPED_TRACE(w.file);
    Model m = robot(w.file);
    ASSERT_EQ(m.n(), w.n);
    ASSERT_EQ(m.fx.size(), size_t(w.n * w.n));
    ASSERT_EQ(m.fq.size(), size_t(w.n * w.n));
    EXPECT_EQ(structural_shape(m.dag, m.fx, w.n), w.fx);
    EXPECT_EQ(structural_shape(m.dag, m.fq, w.n), w.fq);
  }
  // 3-RPR: eq1 = x1^2 + x2^2 - q1^2 does not involve the orientation x3.
  Model m = robot("3rpr.robot");
  EXPECT_EQ(m.fx[2], m.dag.zero());
  EXPECT_NE(m.fx[5], m.dag.zero());
  EXPECT_NE(m.fx[8], m.dag.zero());
}

TEST(JacobianStructure, ShapeClassification) {
  set_working_precision(53);
  Dag d;
  int x = d.var(0), z = d.zero();
  EXPECT_EQ(structural_shape(d, {x, z, z, x}, 2), MatrixShape::Diagonal);
  EXPECT_EQ(structural_shape(d, {x, z, x, x}, 2), MatrixShape::LowerTriangular);
  EXPECT_EQ(structural_shape(d, {x, x, z, x}, 2), MatrixShape::UpperTriangular);
  EXPECT_EQ(structural_shape(d, {x, x, x, x}, 2), MatrixShape::Full);
  EXPECT_EQ(structural_shape(d, {z, z, z, z}, 2), MatrixShape::Diagonal);
}

// ----------------------------------------------------------------- derivative rules

struct DerivCase {
  std::string name;
  Op op;
  int k;
  int arity;
};

void PrintTo(const DerivCase& c, std::ostream* os) { *os << c.name; }

class DerivativeRule : public ::testing::TestWithParam<DerivCase> {};

// Where the operation is differentiable and the point safely inside its domain.
bool good_point(const DerivCase& c, double x, double y) {
  switch (c.op) {
    case Op::Div: return std::abs(y) > 1e-3;
    case Op::Min:
    case Op::Max: return std::abs(x - y) > 1e-6;
    case Op::Sqrt:
    case Op::Log: return x > 1e-3;
    case Op::Abs: return std::abs(x) > 1e-6;
    case Op::Asin:
    case Op::Acos: return std::abs(x) < 0.999;
    case Op::Tan: return std::abs(std::cos(x)) > 1e-2;
    case Op::Pow: return c.k > 0 || std::abs(x) > 1e-3;
    default: return true;
  }
}

TEST_P(DerivativeRule, EnclosesFiniteDifference) {
  const DerivCase& c = GetParam();
  set_working_precision(53);
  aspects_test::ref_prec() = 256;
  Dag dag;
  int x = dag.var(0), y = dag.var(1);
  int node = c.op == Op::Pow ? dag.pow(x, c.k)
             : c.arity == 2  ? dag.binary(c.op, x, y)
                             : dag.unary(c.op, x);
  int dx = dag.derivative(node, 0), dy = dag.derivative(node, 1);
  if (c.arity == 1) {
    EXPECT_EQ(dy, dag.zero());
  }
  EXPECT_EQ(dag.derivative(node, 0), dx) << "derivatives are memoised";
  std::vector<int> prog = dag.closure({dx, dy});
  Evaluator ev(dag);
  std::mt19937 g(31337u + unsigned(c.op) * 17u + unsigned(c.k + 50));
  R h = step();
  int checked = 0;
  for (int it = 0; it < 400; ++it) {
    double s = std::vector<double>{0.01, 1, 3, 30}[size_t(it % 4)];
    double px = aspects_test::uniform(g, -s, s), py = aspects_test::uniform(g, -s, s);
    if (c.op == Op::Sqrt || c.op == Op::Log) px = std::abs(px);
    if (c.op == Op::Asin || c.op == Op::Acos) px = std::fmod(px, 1.0);
    if (!good_point(c, px, py)) continue;
    // Central differences in each variable.
    R d[2];
    for (int v = 0; v < 2; ++v) {
      R a(px), b(py), fa, fb;
      (v == 0 ? a : b) = (v == 0 ? a : b) + h;
      ASSERT_TRUE(aspects_test::exact_op(c.op, c.k, fa.get(), a.get(), b.get(), MPFR_RNDN));
      R a2(px), b2(py);
      (v == 0 ? a2 : b2) = (v == 0 ? a2 : b2) - h;
      ASSERT_TRUE(aspects_test::exact_op(c.op, c.k, fb.get(), a2.get(), b2.get(), MPFR_RNDN));
      d[v] = (fa - fb) / (R(2) * h);
    }
    for (double w : {1e-12, 1e-6}) {
      Box box{aspects_test::ball(R(px), w), aspects_test::ball(R(py), w)};
      EvalStatus st = ev.forward(prog, box);
      ASSERT_NE(st, EvalStatus::Undefined) << c.name << " x=" << px << " y=" << py;
      for (int v = 0; v < 2; ++v) {
        const Interval& e = ev.value(v == 0 ? dx : dy);
        ++checked;
        EXPECT_TRUE(aspects_test::interval_contains(e, d[v]))
            << c.name << ": d/d" << (v == 0 ? "x" : "y") << " at x=" << px << " y=" << py
            << " (box radius " << w << "): finite difference " << d[v].str(25) << " not in "
            << interval_str(e, 25) << "  [derivative: "
            << dag.to_string(v == 0 ? dx : dy, {"x", "y"}) << "]";
      }
    }
  }
  EXPECT_GT(checked, 200);
}

std::vector<DerivCase> deriv_cases() {
  std::vector<DerivCase> v = {
      {"add", Op::Add, 0, 2},   {"sub", Op::Sub, 0, 2},   {"mul", Op::Mul, 0, 2},
      {"div", Op::Div, 0, 2},   {"min", Op::Min, 0, 2},   {"max", Op::Max, 0, 2},
      {"neg", Op::Neg, 0, 1},   {"sqr", Op::Sqr, 0, 1},   {"sqrt", Op::Sqrt, 0, 1},
      {"sin", Op::Sin, 0, 1},   {"cos", Op::Cos, 0, 1},   {"tan", Op::Tan, 0, 1},
      {"exp", Op::Exp, 0, 1},   {"log", Op::Log, 0, 1},   {"abs", Op::Abs, 0, 1},
      {"asin", Op::Asin, 0, 1}, {"acos", Op::Acos, 0, 1}, {"atan", Op::Atan, 0, 1},
  };
  for (int k : {-4, -3, -2, -1, 3, 4, 5})
    v.push_back({(k < 0 ? "pow_m" : "pow_") + std::to_string(k < 0 ? -k : k), Op::Pow, k, 1});
  return v;
}

INSTANTIATE_TEST_SUITE_P(AllOps, DerivativeRule, ::testing::ValuesIn(deriv_cases()),
                         [](const ::testing::TestParamInfo<DerivCase>& info) {
                           return info.param.name;
                         });

}  // namespace
