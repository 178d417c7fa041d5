// The evaluator's two instantiations (core/model/interval_eval.h) at 53 bits: on doubles
// (core/numerics/double_interval.h, core/numerics/evaluator_ops.h) and on MPFI, the same
// ends bit for bit, operation by operation, and node by node on random boxes of every
// robot of robots/ (the equations, both Jacobians and the determinant factors, and every
// HC4-Revise); and a hand-back (nullopt) for what doubles do not take.
//
// Seen failing (each break made in core/numerics/evaluator_ops.h, then reverted):
//  - sqr on doubles as the product a·a (no case for an a holding 0): every robot fails
//    in the forward comparison;
//  - base_angle on doubles with acos' ends swapped ({lo_lo, hi_hi}): the six robots with
//    a cos in an equation fail on an HC4 verdict (forward values still agree); prrp and
//    rprpr pass.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "model/determinant_factors.h"
#include "model/eval.h"
#include "model/interval_eval.h"
#include "model/model.h"

namespace {

using aspects::DInterval;
using aspects::Interval;

// A double with a random sign, a random exponent in [-e, e] and a random mantissa, or
// one of a few exact small values (ties and exact results are where a wrong residual
// test would step outward when it must not).
double random_double(std::mt19937_64& g, int e) {
  std::uniform_int_distribution<int> pick(0, 9), ex(-e, e), small(-8, 8);
  std::uniform_real_distribution<double> m(1, 2);
  if (pick(g) == 0) return small(g) * 0.25;
  double x = std::ldexp(m(g), ex(g));
  return pick(g) < 5 ? -x : x;
}

DInterval random_interval(std::mt19937_64& g, int e) {
  double a = random_double(g, e), b = random_double(g, e);
  if (std::uniform_int_distribution<int>(0, 3)(g) == 0) b = a;  // a point
  return {std::min(a, b), std::max(a, b)};
}

Interval mpfi(const DInterval& x) { return Interval(x.lo, x.hi); }

void expect_same(const DInterval& d, const Interval& m, const char* op, const DInterval& a,
                 const DInterval& b) {
  ASSERT_EQ(d.lo, m.lo_down()) << op << " [" << a.lo << "," << a.hi << "] [" << b.lo << ","
                               << b.hi << "]";
  ASSERT_EQ(d.hi, m.hi_up()) << op << " [" << a.lo << "," << a.hi << "] [" << b.lo << ","
                             << b.hi << "]";
}

}  // namespace

// Away from underflow every end is MPFR's directed rounding; near it (|x| < 2^-900) an
// end may be one ulp wider, never narrower; on overflow the same ends as MPFI.
TEST(DoubleInterval, EndsAreMpfisAt53Bits) {
  aspects::set_working_precision(53);
  std::mt19937_64 g(7);
  for (int e : {4, 60, 600, 1020}) {
    for (int trial = 0; trial < 20000; ++trial) {
      DInterval a = random_interval(g, e), b = random_interval(g, e);
      Interval ma = mpfi(a), mb = mpfi(b), r;
      mpfi_add(r.get(), ma.get(), mb.get());
      DInterval d = aspects::add(a, b);
      if (e < 900) expect_same(d, r, "add", a, b);
      EXPECT_TRUE(d.lo <= r.lo_down() && d.hi >= r.hi_up());
      mpfi_sub(r.get(), ma.get(), mb.get());
      d = aspects::sub(a, b);
      if (e < 900) expect_same(d, r, "sub", a, b);
      mpfi_mul(r.get(), ma.get(), mb.get());
      d = aspects::mul(a, b);
      if (e < 400) expect_same(d, r, "mul", a, b);
      ASSERT_TRUE(d.lo <= r.lo_down() && d.hi >= r.hi_up()) << "mul " << a.lo << " " << b.lo;
      mpfi_sqr(r.get(), ma.get());
      d = aspects::sqr(a);
      if (e < 400) expect_same(d, r, "sqr", a, a);
      ASSERT_TRUE(d.lo <= r.lo_down() && d.hi >= r.hi_up());
      if (!aspects::has_zero(b)) {
        mpfi_div(r.get(), ma.get(), mb.get());
        d = aspects::div(a, b);
        if (e < 400) expect_same(d, r, "div", a, b);
        ASSERT_TRUE(d.lo <= r.lo_down() && d.hi >= r.hi_up()) << "div " << a.lo << " " << b.lo;
      }
      DInterval p{std::fabs(a.lo), std::fabs(a.lo)};
      if (p.lo < std::fabs(a.hi)) p.hi = std::fabs(a.hi);
      else p.lo = std::fabs(a.hi);
      mpfi_sqrt(r.get(), mpfi(p).get());
      d = aspects::sqrt(p);
      if (e < 800) expect_same(d, r, "sqrt", p, p);
      ASSERT_TRUE(d.lo <= r.lo_down() && d.hi >= r.hi_up());
    }
  }
  // Overflow: the largest double below the exact value, and +inf above it.
  DInterval big{DBL_MAX, DBL_MAX}, two{2, 2};
  DInterval d = aspects::mul(big, two);
  EXPECT_EQ(d.lo, DBL_MAX);
  EXPECT_EQ(d.hi, INFINITY);
  d = aspects::add(big, big);
  EXPECT_EQ(d.lo, DBL_MAX);
  EXPECT_EQ(d.hi, INFINITY);
}

// An end that is exact stays put; one that is not moves to the right neighbour.
TEST(DoubleInterval, ExactResultsAreNotWidened) {
  DInterval d = aspects::mul({3, 3}, {0.5, 0.5});
  EXPECT_EQ(d.lo, 1.5);
  EXPECT_EQ(d.hi, 1.5);
  d = aspects::div({1, 1}, {3, 3});
  EXPECT_EQ(d.hi, std::nextafter(d.lo, 1.0));
  EXPECT_LT(d.lo * 3, 1.0 + 1e-15);
  d = aspects::add({1, 1}, {0x1p-60, 0x1p-60});
  EXPECT_EQ(d.lo, 1.0);
  EXPECT_EQ(d.hi, std::nextafter(1.0, 2.0));
  d = aspects::sqrt({4, 4});
  EXPECT_EQ(d.lo, 2);
  EXPECT_EQ(d.hi, 2);
  d = aspects::sqrt({2, 2});
  EXPECT_EQ(d.hi, std::nextafter(d.lo, 2.0));
}

namespace {

using aspects::Box;
using aspects::IntervalEvaluator;

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Every robot model in robots/, by file name.
std::vector<std::string> robot_files() {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(ASPECTS_ROBOTS_DIR))
    if (e.path().extension() == ".robot") names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A random sub-box of the domain, of random width down to about 2^-12 of it.
Box random_box(const Box& dom, std::mt19937_64& g) {
  std::uniform_real_distribution<double> U(0, 1);
  Box box(dom.size());
  for (size_t v = 0; v < dom.size(); ++v) {
    double lo = dom[v].lo_down(), hi = dom[v].hi_up();
    double c = lo + (hi - lo) * U(g), w = (hi - lo) * std::ldexp(U(g), -int(U(g) * 12));
    box[v].set_hull(std::max(lo, c - w / 2), std::min(hi, c + w / 2));
  }
  return box;
}

bool same_ends(const DInterval& d, const Interval& m) {
  return d.lo == m.lo_down() && d.hi == m.hi_up();
}

bool same_boxes(const Box& x, const Box& y) {
  for (size_t v = 0; v < x.size(); ++v)
    if (x[v].lo_down() != y[v].lo_down() || x[v].hi_up() != y[v].hi_up()) return false;
  return true;
}

// An evaluator without the double fast path.
std::unique_ptr<aspects::Evaluator> mpfi_evaluator(const aspects::Dag& dag) {
  return std::make_unique<aspects::Evaluator>(dag, aspects::Arithmetic::MpfiOnly);
}

class BothInstantiations : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST(BothInstantiations, EveryRobotOfTheDirectoryIsCompared) {
  const std::vector<std::string> files = robot_files();
  for (const char* known : {"3rpr.robot", "3rrr_star.robot", "prrp.robot", "rprpr.robot",
                            "rrrrr.robot", "rrrrr_collisions.robot", "rrrrr_joint_limit.robot",
                            "rrrrr_obstacle.robot"})
    EXPECT_NE(std::find(files.begin(), files.end(), known), files.end()) << known;
}

// Every node of the equations, both Jacobians and the determinant factors, and every
// HC4-Revise on each equation: the same status, verdicts and ends on doubles as on MPFI.
TEST_P(BothInstantiations, SameValuesAndContractions) {
  aspects::set_working_precision(53);
  const std::string path = std::string(ASPECTS_ROBOTS_DIR) + "/" + GetParam();
  aspects::Model m = aspects::parse_model(read(path), path);
  const std::vector<aspects::Factor> factors = aspects::determinant_factors(m);
  std::vector<int> roots = m.equations;
  roots.insert(roots.end(), m.fx.begin(), m.fx.end());
  roots.insert(roots.end(), m.fq.begin(), m.fq.end());
  for (const aspects::Factor& f : factors) roots.push_back(f.node);
  const std::vector<int> program = m.dag.closure(roots);
  IntervalEvaluator<DInterval> fast(m.dag);
  IntervalEvaluator<Interval> slow(m.dag);
  const Box dom = m.initial_box();
  std::mt19937_64 g(2026);
  int contracted = 0, infeasible = 0, partial = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const Box box = random_box(dom, g);
    std::optional<aspects::EvalStatus> s = fast.forward(program, box);
    ASSERT_TRUE(s.has_value()) << GetParam() << " trial " << trial;
    ASSERT_EQ(*s, *slow.forward(program, box));
    if (*s != aspects::EvalStatus::Defined) ++partial;
    for (int id : program)
      ASSERT_TRUE(same_ends(fast.value(id), slow.value(id)))
          << GetParam() << " trial " << trial << " node " << id << ": "
          << fast.value(id).lo << " " << fast.value(id).hi << " vs " << slow.value(id).str();
    for (int eq : m.equations) {
      const std::vector<int> p = m.dag.closure({eq});
      Box bf = box, bs = box;
      std::optional<bool> ok = fast.hc4_revise(p, eq, {0, 0}, bf);
      ASSERT_TRUE(ok.has_value());
      ASSERT_EQ(*ok, *slow.hc4_revise(p, eq, Interval(0.0), bs));
      ASSERT_TRUE(same_boxes(bf, bs)) << GetParam() << " trial " << trial;
      if (!*ok) {
        ASSERT_TRUE(same_boxes(bf, box)) << "a rejected box is left as it was";
        ++infeasible;
      } else if (!same_boxes(bf, box)) {
        ++contracted;
      }
    }
  }
  // The comparison covered contractions and rejections, not only unchanged boxes.
  EXPECT_GT(contracted, 50) << GetParam();
  EXPECT_GT(infeasible, 10) << GetParam();
  EXPECT_LT(partial, 600) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Robots, BothInstantiations, ::testing::ValuesIn(robot_files()),
                         [](const auto& info) {
                           std::string s = info.param;
                           return s.substr(0, s.find('.'));
                         });

// What doubles do not take they hand back, with the box untouched, and the facade's
// answer is MPFI's.
TEST(DoubleEval, HandsBackWhatItDoesNotTake) {
  aspects::set_working_precision(53);
  aspects::Dag dag;
  const int x = dag.var(0);
  const int ex = dag.unary(aspects::Op::Exp, x);
  const int inv = dag.binary(aspects::Op::Div, dag.one(), x);
  const int root = dag.unary(aspects::Op::Sqrt, x);
  const int cube = dag.pow(x, 3);
  const int inv_cube = dag.pow(x, -3);
  const int cube_minus = dag.binary(aspects::Op::Sub, cube, dag.constant(8.0));
  IntervalEvaluator<DInterval> fast(dag);
  aspects::Evaluator with(dag);
  std::unique_ptr<aspects::Evaluator> mpfi = mpfi_evaluator(dag);
  aspects::Evaluator& without = *mpfi;
  const Box pos{Interval(1, 4)}, straddle{Interval(-1, 4)};
  Box empty{Interval(1, 2)};
  ASSERT_FALSE(empty[0].intersect(Interval(3, 4)));
  struct Case {
    int node;
    Box box;
    bool taken;
  } cases[] = {{ex, pos, false},       {inv, pos, true},        {inv, straddle, false},
               {root, pos, true},      {root, straddle, false}, {cube, straddle, true},
               {inv_cube, pos, false}, {x, empty, false}};
  for (const Case& c : cases) {
    const std::vector<int> p = dag.closure({c.node});
    EXPECT_EQ(fast.forward(p, c.box).has_value(), c.taken) << dag.to_string(c.node, {"x"});
    EXPECT_EQ(with.forward(p, c.box), without.forward(p, c.box));
    EXPECT_EQ(with.value(c.node).lo_down(), without.value(c.node).lo_down());
    EXPECT_EQ(with.value(c.node).hi_up(), without.value(c.node).hi_up());
  }
  EXPECT_EQ(with.forward(dag.closure({inv}), straddle), aspects::EvalStatus::Partial);
  // x^3 = 8 needs a cube root backward: handed back, and MPFI contracts [-1, 4] to [2, 2].
  const std::vector<int> p = dag.closure({cube_minus});
  Box b = straddle;
  EXPECT_FALSE(fast.hc4_revise(p, cube_minus, {0, 0}, b).has_value());
  EXPECT_EQ(b[0].lo_down(), -1);  // untouched
  EXPECT_EQ(b[0].hi_up(), 4);
  ASSERT_TRUE(with.hc4_revise(p, cube_minus, Interval(0.0), b));
  EXPECT_EQ(b[0].lo_down(), 2);
  EXPECT_EQ(b[0].hi_up(), 2);
}

// The bit-level neighbours agree with std::nextafter, across zero, subnormals and ±∞.
TEST(DoubleInterval, NeighboursAreNextafters) {
  std::mt19937_64 g(3);
  std::vector<double> xs = {0.0, -0.0, DBL_TRUE_MIN, -DBL_TRUE_MIN, DBL_MIN, -DBL_MIN, DBL_MAX,
                            -DBL_MAX, INFINITY, -INFINITY, 1.0, -1.0};
  for (int i = 0; i < 10000; ++i) xs.push_back(random_double(g, 1020));
  for (double x : xs) {
    EXPECT_EQ(aspects::dround::next_up(x), std::nextafter(x, INFINITY)) << x;
    EXPECT_EQ(aspects::dround::next_down(x), std::nextafter(x, -INFINITY)) << x;
  }
}
