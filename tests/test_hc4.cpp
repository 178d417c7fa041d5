// HC4-Revise (ModelEvaluator::hc4) never removes a solution: for every robot model of
// robots/, random points of the constraint surface (computed in MPFR at 256 bits, see
// robot_refs.h), random boxes around them, and repeated HC4 passes over all equations
// keep the point inside the box and never report "no solution". Plus explicit cases
// where HC4 must contract and must reject.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "model/eval.h"
#include "model/expr.h"
#include "model/model.h"
#include "model/model_eval.h"
#include "robot_refs.h"
#include "test_util.h"

using namespace aspects;
using aspects_test::interval_str;
using aspects_test::Point;
using aspects_test::R;
using aspects_test::RobotRef;

namespace {

std::string point_str(const Model& m, const Point& p) {
  std::string s;
  for (size_t j = 0; j < p.size(); ++j) s += " " + m.vars[j].name + "=" + p[j].str(20);
  return s;
}

std::string box_str(const Model& m, const Box& b) {
  std::string s;
  for (size_t j = 0; j < b.size(); ++j) s += " " + m.vars[j].name + " in " + interval_str(b[j], 20);
  return s;
}

bool point_in_box(const Box& b, const Point& p, size_t& bad) {
  for (size_t j = 0; j < p.size(); ++j)
    if (!aspects_test::interval_contains(b[j], p[j])) {
      bad = j;
      return false;
    }
  return true;
}

bool is_fixed(const Interval& d) { return mpfr_equal_p(&d.get()->left, &d.get()->right); }

class Hc4Robot : public ::testing::TestWithParam<RobotRef> {
 protected:
  void SetUp() override {
    set_working_precision(53);
    aspects_test::ref_prec() = 256;
  }
};

// Sanity of the reference: the sampled points solve the equations and lie in the domain.
TEST_P(Hc4Robot, ReferenceSolutionsAreOnTheSurfaceAndInTheDomain) {
  const RobotRef& ref = GetParam();
  Model m = load_model(ref.path());
  ASSERT_EQ(m.name, ref.name);
  ASSERT_EQ(m.n(), ref.n);
  ASSERT_EQ(m.var_names(), ref.vars);
  std::mt19937 g(4242);
  for (int k = 0; k < 50; ++k) {
    Point p = ref.solution(g);
    for (const R& r : ref.f(p)) EXPECT_LT(mpfr_cmpabs(r.get(), R(1e-60).get()), 0) << r.str();
    for (size_t j = 0; j < p.size(); ++j)
      EXPECT_TRUE(aspects_test::interval_contains(m.vars[j].domain, p[j]))
          << m.vars[j].name << "=" << p[j].str() << " outside " << interval_str(m.vars[j].domain);
  }
}

TEST_P(Hc4Robot, NeverRemovesASolution) {
  const RobotRef& ref = GetParam();
  Model m = load_model(ref.path());
  ASSERT_EQ(m.var_names(), ref.vars);
  ModelEvaluator me(m);
  const Box domain = m.initial_box();
  const int nv = int(m.vars.size());
  std::mt19937 g(20240611u + unsigned(ref.n) * 7u + unsigned(ref.file.size()));
  static const double radii[] = {0.0, 1e-14, 1e-10, 1e-6, 1e-3, 1e-2, 0.1, 0.5, 2, 10, 100};
  const int nr = int(sizeof radii / sizeof radii[0]);
  std::uniform_int_distribution<int> pick(0, nr - 1);
  int boxes = 0, contracted = 0;
  std::vector<Interval> f;
  for (int k = 0; k < 120; ++k) {
    Point p = ref.solution(g);
    for (int kb = 0; kb < 8; ++kb) {
      Box box;
      if (kb == 0) {
        box = domain;  // the whole initial box
      } else {
        bool same = kb % 3 == 0;  // the same radius for every variable
        int common = pick(g);
        for (int j = 0; j < nv; ++j) {
          if (is_fixed(domain[j])) {
            box.push_back(domain[j]);
            continue;
          }
          double rl = radii[same ? common : pick(g)], rh = radii[same ? common : pick(g)];
          Interval b = aspects_test::ball2(p[j], rl, rh);
          ASSERT_TRUE(b.intersect(domain[j]));
          box.push_back(b);
        }
      }
      size_t bad = 0;
      ASSERT_TRUE(point_in_box(box, p, bad)) << "test setup: " << point_str(m, p);
      const Box before = box;
      ++boxes;
      for (int round = 0; round < 4; ++round) {
        for (int i = 0; i < m.n(); ++i) {
          bool ok = me.hc4(i, box);
          ASSERT_TRUE(ok) << ref.name << ": hc4 on equation " << i + 1
                          << " rejected a box holding the solution" << point_str(m, p)
                          << "\nbox before:" << box_str(m, before);
          ASSERT_TRUE(point_in_box(box, p, bad))
              << ref.name << ": hc4 on equation " << i + 1 << " (round " << round
              << ") removed the solution: " << m.vars[bad].name << "=" << p[bad].str(25)
              << " not in " << interval_str(box[bad], 25) << "\nsolution:" << point_str(m, p)
              << "\nbox before:" << box_str(m, before) << "\nbox after:" << box_str(m, box);
        }
      }
      // The contracted box still holds a solution: every equation's range holds 0.
      me.equations(box, f);
      for (int i = 0; i < m.n(); ++i)
        EXPECT_TRUE(f[i].contains(0.0)) << "equation " << i + 1 << " range " << interval_str(f[i]);
      for (int j = 0; j < nv; ++j)
        if (box[j].width_up() < before[j].width_up()) {
          ++contracted;
          break;
        }
    }
  }
  // HC4 must have done something on these boxes (otherwise the test proves nothing).
  EXPECT_GT(contracted, boxes / 4) << contracted << " of " << boxes << " boxes contracted";
}

INSTANTIATE_TEST_SUITE_P(Robots, Hc4Robot, ::testing::ValuesIn(aspects_test::robot_refs()),
                         [](const ::testing::TestParamInfo<RobotRef>& info) {
                           std::string s = info.param.file.substr(0, info.param.file.find('.'));
                           return "r" + s;
                         });

// ----------------------------------------------------------------- per operation

// HC4-Revise of one operation: for op(x, y) in T, where T is the tightest interval (at
// the working precision) around the exact value at a point p, or a random widening of
// it, the point p is never removed from a box around it.
struct OpCase {
  std::string name;
  Op op;
  int k;       // Pow exponent
  int arity;   // 1: op(x); 2: op(x, y); 3: sqr(x - y) (nested); 4: sqrt(x*y) + y
};

struct OpParam {
  OpCase c;
  long prec;  // working precision; 24 bits makes the double points off-grid, so that
              // a rounding error of one ulp in a projection can exclude them
};

void PrintTo(const OpParam& p, std::ostream* os) { *os << p.c.name << " at " << p.prec << " bits"; }

class Hc4Op : public ::testing::TestWithParam<OpParam> {};

// Exact value of the case's expression at (a, b), rounded with rnd; false if undefined.
bool case_value(const OpCase& c, mpfr_ptr out, mpfr_srcptr a, mpfr_srcptr b, mpfr_rnd_t rnd) {
  if (c.arity == 3) {
    mpfr_t d;
    mpfr_init2(d, 1024);
    mpfr_sub(d, a, b, MPFR_RNDN);  // exact: doubles, 1024 bits
    mpfr_sqr(out, d, rnd);
    mpfr_clear(d);
    return true;
  }
  if (c.arity == 4) {
    if (mpfr_sgn(a) * mpfr_sgn(b) < 0) return false;
    mpfr_t d;
    mpfr_init2(d, 4096);
    mpfr_mul(d, a, b, MPFR_RNDN);  // exact
    // sqrt(d) + b: correctly rounded only through a higher-precision step; use 4096
    // bits and directed rounding on both steps, which brackets the exact value.
    mpfr_sqrt(d, d, rnd);
    mpfr_add(out, d, b, rnd);
    mpfr_clear(d);
    return true;
  }
  return aspects_test::exact_op(c.op, c.k, out, a, b, rnd);
}

TEST_P(Hc4Op, NeverRemovesAPointOfTheConstraint) {
  const OpCase& c = GetParam().c;
  const long prec = GetParam().prec;
  set_working_precision(prec);
  Dag dag;
  int x = dag.var(0), y = dag.var(1);
  int node;
  switch (c.arity) {
    case 1: node = c.op == Op::Pow ? dag.pow(x, c.k) : dag.unary(c.op, x); break;
    case 2: node = dag.binary(c.op, x, y); break;
    case 3: node = dag.unary(Op::Sqr, dag.binary(Op::Sub, x, y)); break;
    default:
      node = dag.binary(Op::Add, dag.unary(Op::Sqrt, dag.binary(Op::Mul, x, y)), y);
      break;
  }
  std::vector<int> prog = dag.closure({node});
  Evaluator ev(dag);
  std::mt19937 g(555u + unsigned(c.op) * 101u + unsigned(c.k + 20) * 7u + unsigned(c.arity) +
                 unsigned(prec));
  static const double scales[] = {1e-3, 0.5, 1, 3, 10, 1000};
  static const double radii[] = {0, 1e-15, 1e-12, 1e-6, 1e-2, 1, 100};
  std::uniform_int_distribution<int> ps(0, 5), pr(0, 6), pw(0, 3);
  mpfr_t a, b, lo, hi, t;
  mpfr_inits2(53, a, b, lo, hi, t, (mpfr_ptr)0);
  int checked = 0, contracted = 0;
  for (int it = 0; it < 1500; ++it) {
    double s = scales[ps(g)];
    if (c.op == Op::Exp && s > 10) s = 10;
    double px = aspects_test::uniform(g, -s, s), py = aspects_test::uniform(g, -s, s);
    if (c.op == Op::Sqrt || c.op == Op::Log) px = std::abs(px);
    if (c.op == Op::Asin || c.op == Op::Acos) px = std::fmod(px, 1.0);
    if (c.arity == 4) py = std::abs(py), px = std::abs(px);
    if (it % 50 == 0) px = 0, py = 0;  // a special point
    mpfr_set_d(a, px, MPFR_RNDN);
    mpfr_set_d(b, py, MPFR_RNDN);
    if (!case_value(c, lo, a, b, MPFR_RNDD)) continue;
    case_value(c, hi, a, b, MPFR_RNDU);
    // Target: tight enclosure of f(p), or widened by a random amount on either side.
    int widen = pw(g);
    if (widen & 1) {
      mpfr_set_d(t, radii[pr(g)], MPFR_RNDU);
      mpfr_sub(lo, lo, t, MPFR_RNDD);
    }
    if (widen & 2) {
      mpfr_set_d(t, radii[pr(g)], MPFR_RNDU);
      mpfr_add(hi, hi, t, MPFR_RNDU);
    }
    Interval target;
    mpfi_interv_fr(target.get(), lo, hi);
    Box box{aspects_test::ball2(R(px), radii[pr(g)], radii[pr(g)]),
            aspects_test::ball2(R(py), radii[pr(g)], radii[pr(g)])};
    const Box before = box;
    ++checked;
    bool ok = ev.hc4_revise(prog, node, target, box);
    ASSERT_TRUE(ok) << c.name << " at " << prec << " bits: rejected x=" << px << " y=" << py << " target "
                    << interval_str(target, 20) << " box x in " << interval_str(before[0], 20)
                    << ", y in " << interval_str(before[1], 20);
    bool in = box[0].contains(px) && box[1].contains(py);
    ASSERT_TRUE(in) << c.name << " at " << prec << " bits: removed x=" << px << " y=" << py << " target "
                    << interval_str(target, 20) << "\nbox before: x in "
                    << interval_str(before[0], 20) << ", y in " << interval_str(before[1], 20)
                    << "\nbox after:  x in " << interval_str(box[0], 20) << ", y in "
                    << interval_str(box[1], 20);
    if (box[0].width_up() < before[0].width_up() || box[1].width_up() < before[1].width_up())
      ++contracted;
  }
  mpfr_clears(a, b, lo, hi, t, (mpfr_ptr)0);
  EXPECT_GT(checked, 1000);
  // Every case with a non-trivial backward rule must contract sometimes.
  bool projects = !(c.op == Op::Sin || c.op == Op::Cos || c.op == Op::Tan ||
                    (c.op == Op::Pow && c.k < 0));
  if (projects) {
    EXPECT_GT(contracted, checked / 20) << contracted << " of " << checked;
  }
}

std::vector<OpCase> hc4_op_cases() {
  std::vector<OpCase> v = {
      {"add", Op::Add, 0, 2},   {"sub", Op::Sub, 0, 2},   {"mul", Op::Mul, 0, 2},
      {"div", Op::Div, 0, 2},   {"min", Op::Min, 0, 2},   {"max", Op::Max, 0, 2},
      {"neg", Op::Neg, 0, 1},   {"sqr", Op::Sqr, 0, 1},   {"sqrt", Op::Sqrt, 0, 1},
      {"sin", Op::Sin, 0, 1},   {"cos", Op::Cos, 0, 1},   {"tan", Op::Tan, 0, 1},
      {"exp", Op::Exp, 0, 1},   {"log", Op::Log, 0, 1},   {"abs", Op::Abs, 0, 1},
      {"asin", Op::Asin, 0, 1}, {"acos", Op::Acos, 0, 1}, {"atan", Op::Atan, 0, 1},
      {"sqr_of_difference", Op::Sqr, 0, 3}, {"sqrt_of_product_plus_y", Op::Sqrt, 0, 4},
  };
  for (int k : {-3, -2, 3, 4, 5, 6})
    v.push_back({(k < 0 ? "pow_m" : "pow_") + std::to_string(k < 0 ? -k : k), Op::Pow, k, 1});
  return v;
}

std::vector<OpParam> hc4_op_params() {
  std::vector<OpParam> v;
  for (long prec : {24L, 53L})
    for (const OpCase& c : hc4_op_cases()) v.push_back({c, prec});
  return v;
}

INSTANTIATE_TEST_SUITE_P(AllOps, Hc4Op, ::testing::ValuesIn(hc4_op_params()),
                         [](const ::testing::TestParamInfo<OpParam>& info) {
                           return info.param.c.name + "_prec" + std::to_string(info.param.prec);
                         });

// ----------------------------------------------------------------- explicit cases

Model prrp() { return load_model(std::string(ASPECTS_ROBOTS_DIR) + "/prrp.robot"); }

TEST(Hc4Explicit, PrrpContractsToTheUnitCircle) {
  set_working_precision(53);
  Model m = prrp();
  ModelEvaluator me(m);
  Box box{Interval(0.9, 2.0), Interval(-2.0, 2.0)};  // x, q
  ASSERT_TRUE(me.hc4(0, box));
  // x^2 + q^2 = 1 with x >= 0.9: x in [0.9, 1], |q| <= sqrt(1 - 0.81) = sqrt(0.19).
  EXPECT_EQ(box[0].lo_down(), 0.9) << interval_str(box[0]);
  EXPECT_LE(box[0].hi_up(), 1.0 + 1e-15) << interval_str(box[0]);
  EXPECT_GE(box[0].hi_up(), 1.0) << interval_str(box[0]);
  R r019 = R(1) - R(0.9) * R(0.9);
  R sq = sqrt(r019);
  EXPECT_TRUE(aspects_test::interval_contains(box[1], sq)) << interval_str(box[1]);
  EXPECT_TRUE(aspects_test::interval_contains(box[1], -sq)) << interval_str(box[1]);
  EXPECT_LE(box[1].hi_up(), sq.d() + 1e-12) << interval_str(box[1]);
  EXPECT_GE(box[1].lo_down(), -sq.d() - 1e-12) << interval_str(box[1]);
}

TEST(Hc4Explicit, PrrpRejectsABoxWithoutSolution) {
  set_working_precision(53);
  Model m = prrp();
  ModelEvaluator me(m);
  Box box{Interval(1.5, 2.0), Interval(1.5, 2.0)};
  EXPECT_FALSE(me.hc4(0, box));
  // A tiny box near (but off) the circle: 0.6^2 + 0.9^2 = 1.17.
  Box near{Interval(0.6, 0.6 + 1e-9), Interval(0.9, 0.9 + 1e-9)};
  EXPECT_FALSE(me.hc4(0, near));
  // Inside the circle, away from it: x, q in [0, 0.5].
  Box inner{Interval(0.0, 0.5), Interval(-0.5, 0.5)};
  EXPECT_FALSE(me.hc4(0, inner));
}

TEST(Hc4Explicit, PrrpKeepsTheExactSolutionOnePointBox) {
  set_working_precision(53);
  Model m = prrp();
  ModelEvaluator me(m);
  Box box{Interval(1.0), Interval(0.0)};  // (1, 0) is an exact solution
  ASSERT_TRUE(me.hc4(0, box));
  EXPECT_EQ(box[0].lo_down(), 1.0);
  EXPECT_EQ(box[0].hi_up(), 1.0);
  EXPECT_EQ(box[1].lo_down(), 0.0);
  EXPECT_EQ(box[1].hi_up(), 0.0);
}

TEST(Hc4Explicit, RprprBoundsTheArmByTheCommandRange) {
  set_working_precision(53);
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rprpr.robot");
  ModelEvaluator me(m);
  Box box = m.initial_box();  // x in [-20, 20]^2, q1 in [2, 6], q2 in [4, 9]
  ASSERT_TRUE(me.hc4(0, box));
  // x1^2 + x2^2 = q1^2 <= 36: both coordinates in [-6, 6] (exact: sqrt(36) = 6).
  EXPECT_EQ(box[0].lo_down(), -6.0) << interval_str(box[0]);
  EXPECT_EQ(box[0].hi_up(), 6.0) << interval_str(box[0]);
  EXPECT_EQ(box[1].lo_down(), -6.0) << interval_str(box[1]);
  EXPECT_EQ(box[1].hi_up(), 6.0) << interval_str(box[1]);
  EXPECT_EQ(box[2].lo_down(), 2.0);
  EXPECT_EQ(box[2].hi_up(), 6.0);
  // Equation 2 then: (x1 - 9)^2 <= 81 - 0 gives x1 >= 0.
  ASSERT_TRUE(me.hc4(1, box));
  EXPECT_EQ(box[0].lo_down(), 0.0) << interval_str(box[0]);
  EXPECT_EQ(box[0].hi_up(), 6.0) << interval_str(box[0]);
  // q2^2 = (x1 - 9)^2 + x2^2 >= 9: q2 unchanged at [4, 9]; q2 >= 3 already.
  EXPECT_EQ(box[3].lo_down(), 4.0);
  EXPECT_EQ(box[3].hi_up(), 9.0);
}

}  // namespace
