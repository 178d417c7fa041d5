// Enclosure property of the forward interval evaluation (core/model/eval.cpp): for random
// boxes and random points of those boxes, the MPFI value of every operation contains
// the exact value at the point. The reference is MPFR at (at least) 4x the working
// precision, rounded both down and up: both roundings must lie inside the interval.
// Also: decimal literals are enclosed, never rounded through a double.
#include <gtest/gtest.h>

#include <gmp.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "model/eval.h"
#include "model/expr.h"
#include "numerics/interval.h"
#include "model/model.h"
#include "test_util.h"

using namespace aspects;
using aspects_test::interval_str;
using aspects_test::mpfr_str;

namespace {

// ---------------------------------------------------------------- reference values

class Mp {  // plain RAII mpfr_t at a given precision
 public:
  explicit Mp(mpfr_prec_t p) { mpfr_init2(v, p); }
  ~Mp() { mpfr_clear(v); }
  Mp(const Mp&) = delete;
  Mp& operator=(const Mp&) = delete;
  mpfr_t v;
};

enum class Dom { General, NonNeg, Unit, ExpArg, PowArg };

struct OpCase {
  std::string name;
  int arity;       // 1 or 2
  Op op;           // node operation (Pow: use k)
  int k;           // Pow exponent
  bool same;       // binary(op, x, x): both operands are the same node
  Dom dom;
};

std::vector<OpCase> all_ops() {
  std::vector<OpCase> v = {
      {"add", 2, Op::Add, 0, false, Dom::General},
      {"sub", 2, Op::Sub, 0, false, Dom::General},
      {"mul", 2, Op::Mul, 0, false, Dom::General},
      {"mul_same", 1, Op::Mul, 0, true, Dom::General},  // x*x: the sqr path
      {"sub_same", 1, Op::Sub, 0, true, Dom::General},  // x-x
      {"div", 2, Op::Div, 0, false, Dom::General},
      {"div_same", 1, Op::Div, 0, true, Dom::General},  // x/x
      {"min", 2, Op::Min, 0, false, Dom::General},
      {"max", 2, Op::Max, 0, false, Dom::General},
      {"neg", 1, Op::Neg, 0, false, Dom::General},
      {"sqr", 1, Op::Sqr, 0, false, Dom::General},
      {"sqrt", 1, Op::Sqrt, 0, false, Dom::NonNeg},
      {"sin", 1, Op::Sin, 0, false, Dom::General},
      {"cos", 1, Op::Cos, 0, false, Dom::General},
      {"tan", 1, Op::Tan, 0, false, Dom::General},
      {"exp", 1, Op::Exp, 0, false, Dom::ExpArg},
      {"log", 1, Op::Log, 0, false, Dom::NonNeg},
      {"abs", 1, Op::Abs, 0, false, Dom::General},
      {"asin", 1, Op::Asin, 0, false, Dom::Unit},
      {"acos", 1, Op::Acos, 0, false, Dom::Unit},
      {"atan", 1, Op::Atan, 0, false, Dom::General},
      {"sign", 1, Op::Sign, 0, false, Dom::General},
      {"step", 2, Op::Step, 0, false, Dom::General},
  };
  for (int k : {-7, -5, -4, -3, -2, -1, 3, 4, 5, 6, 7, 10, 13})
    v.push_back({(k < 0 ? "pow_m" : "pow_") + std::to_string(k < 0 ? -k : k), 1, Op::Pow, k,
                 false, Dom::PowArg});
  return v;
}

// Exact operation at a point, rounded with rnd into out. False when undefined there.
bool reference(const OpCase& c, mpfr_ptr out, mpfr_srcptr a, mpfr_srcptr b, mpfr_rnd_t rnd) {
  return aspects_test::exact_op(c.op, c.k, out, a, c.same ? a : b, rnd);
}

// ---------------------------------------------------------------- random boxes

struct Gen {
  std::mt19937 g;
  explicit Gen(unsigned seed) : g(seed) {}
  double u(double lo, double hi) { return aspects_test::uniform(g, lo, hi); }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(g); }

  // Endpoints of a random box for one operand.
  std::pair<double, double> box(Dom d) {
    static const double scales_general[] = {1e-9, 1e-3, 0.25, 1, 1.5, 3, 10, 100, 1e4, 1e8};
    static const double scales_exp[] = {1e-9, 1e-3, 0.25, 1, 3, 10, 100, 700, 5000};
    static const double scales_unit[] = {1e-9, 1e-3, 0.1, 0.5, 1, 1.2, 2};
    static const double scales_pow[] = {1e-9, 1e-3, 0.1, 0.5, 1, 1.5, 3, 10, 1000};
    const double* scales;
    int ns;
    switch (d) {
      case Dom::ExpArg: scales = scales_exp, ns = 9; break;
      case Dom::Unit: scales = scales_unit, ns = 7; break;
      case Dom::PowArg: scales = scales_pow, ns = 9; break;
      default: scales = scales_general, ns = 10; break;
    }
    double s = scales[pick(ns)];
    double c;
    int special = pick(10);
    if (special == 0) {
      c = 0.0;
    } else if (special == 1) {
      static const double sp[] = {1.0, -1.0, M_PI / 2, -M_PI / 2, M_PI, 3 * M_PI / 2, 0.5};
      c = sp[pick(7)];
    } else if (d == Dom::NonNeg) {
      c = u(-0.2 * s, s);
    } else {
      c = u(-s, s);
    }
    double w;
    switch (pick(5)) {
      case 0: w = 0; break;           // degenerate box
      case 1: w = 1e-12 * s; break;
      case 2: w = 1e-3 * s; break;
      default: w = s; break;
    }
    double lo = c - w * u(0, 1), hi = c + w * u(0, 1);
    if (lo > hi) std::swap(lo, hi);
    return {lo, hi};
  }

  // Points of [lo, hi]: both endpoints, random interior points, and the doubles next
  // to multiples of pi/2 and to 0, +-1 that lie inside (extrema of sin, cos, ...).
  std::vector<double> points(double lo, double hi, int nrandom) {
    std::vector<double> p = {lo, hi};
    for (int i = 0; i < nrandom; ++i) p.push_back(u(lo, hi));
    for (double s : {0.0, 1.0, -1.0})
      if (lo <= s && s <= hi) p.push_back(s);
    double k0 = std::ceil(lo / (M_PI / 2));
    for (int i = 0; i < 4; ++i) {
      double t = (k0 + i) * (M_PI / 2);
      for (double q : {t, std::nextafter(t, -INFINITY), std::nextafter(t, INFINITY)})
        if (lo <= q && q <= hi) p.push_back(q);
    }
    return p;
  }
};

int build(Dag& dag, const OpCase& c) {
  int x = dag.var(0), y = dag.var(1);
  if (c.op == Op::Pow) return dag.pow(x, c.k);
  if (c.same) return dag.binary(c.op, x, x);
  if (c.arity == 2) return dag.binary(c.op, x, y);
  return dag.unary(c.op, x);
}

struct Param {
  OpCase op;
  long prec;
};

void PrintTo(const Param& p, std::ostream* os) { *os << p.op.name << " at " << p.prec << " bits"; }

class EnclosureTest : public ::testing::TestWithParam<Param> {};

TEST_P(EnclosureTest, ContainsExactValueAtSampledPoints) {
  const OpCase& c = GetParam().op;
  const long prec = GetParam().prec;
  set_working_precision(prec);
  const mpfr_prec_t ref_prec = std::max<mpfr_prec_t>(212, 4 * prec);

  Dag dag;
  int node = build(dag, c);
  if (c.op == Op::Pow) {
    ASSERT_EQ(dag.node(node).op, Op::Pow) << c.name;
    ASSERT_EQ(dag.node(node).k, c.k) << c.name;
  } else {
    ASSERT_EQ(dag.node(node).op, c.op) << c.name;
  }
  std::vector<int> prog = dag.closure({node});
  Evaluator ev(dag);

  Gen gen(12345u + unsigned(c.op) * 977u + unsigned(c.k + 100) * 31u + unsigned(prec));
  Mp a(ref_prec), b(ref_prec), down(ref_prec), up(ref_prec);
  long checked = 0;
  const int kBoxes = 250;
  for (int ibox = 0; ibox < kBoxes; ++ibox) {
    auto [lx, hx] = gen.box(c.dom);
    auto [ly, hy] = gen.box(c.dom);
    Box box{Interval(lx, hx), Interval(ly, hy)};
    EvalStatus status = ev.forward(prog, box);
    const Interval& r = ev.value(node);
    std::vector<double> px = gen.points(lx, hx, 6);
    std::vector<double> py = c.arity == 2 ? gen.points(ly, hy, 6) : std::vector<double>{ly};
    int failures = 0;
    for (size_t i = 0; i < px.size(); ++i) {
      for (size_t j = 0; j < py.size(); ++j) {
        if (c.arity == 2 && j != i && j != 0 && i != 0) continue;  // pairs: diagonal + cross
        mpfr_set_d(a.v, px[i], MPFR_RNDN);  // exact: ref_prec >= 53
        mpfr_set_d(b.v, py[j], MPFR_RNDN);
        // The step's value at its jump (x = y) is unspecified: nothing to check there.
        if (c.op == Op::Step && mpfr_equal_p(a.v, b.v)) continue;
        bool defined = reference(c, down.v, a.v, b.v, MPFR_RNDD);
        reference(c, up.v, a.v, b.v, MPFR_RNDU);
        if (!defined) {
          EXPECT_NE(status, EvalStatus::Defined)
              << c.name << " prec " << prec << ": undefined at x=" << px[i] << " y=" << py[j]
              << " but forward() says Defined on x in [" << lx << ", " << hx << "], y in ["
              << ly << ", " << hy << "]";
          continue;
        }
        ++checked;
        EXPECT_NE(status, EvalStatus::Undefined)
            << c.name << ": defined at x=" << px[i] << " but status Undefined";
        bool ok = aspects_test::interval_contains(r, down.v) &&
                  aspects_test::interval_contains(r, up.v);
        if (!ok && ++failures <= 3) {
          ADD_FAILURE() << c.name << " prec " << prec << ": box x in [" << lx << ", " << hx
                        << "], y in [" << ly << ", " << hy << "], point x=" << px[i]
                        << " y=" << py[j] << ": exact value in [" << mpfr_str(down.v, 30)
                        << ", " << mpfr_str(up.v, 30) << "] not inside " << interval_str(r, 30);
        }
      }
    }
  }
  // The test has teeth only if a fair number of defined points was checked.
  EXPECT_GT(checked, kBoxes) << c.name;
}

std::vector<Param> all_params() {
  std::vector<Param> v;
  for (long prec : {24L, 53L, 113L})
    for (const OpCase& c : all_ops()) v.push_back({c, prec});
  return v;
}

INSTANTIATE_TEST_SUITE_P(AllOps, EnclosureTest, ::testing::ValuesIn(all_params()),
                         [](const ::testing::TestParamInfo<Param>& info) {
                           return info.param.op.name + "_prec" +
                                  std::to_string(info.param.prec);
                         });

// A composite expression with shared sub-expressions (hash-consed nodes).
TEST(Enclosure, CompositeExpressionWithSharedNodes) {
  set_working_precision(53);
  aspects_test::ref_prec() = 256;
  using aspects_test::R;
  Dag dag;
  int x = dag.var(0), y = dag.var(1);
  // f = (x*y + sin(x))^2 - exp(y) / (x^2 + 1) + atan(x - y) * cos(x*y)
  int xy = dag.binary(Op::Mul, x, y);
  int t1 = dag.pow(dag.binary(Op::Add, xy, dag.unary(Op::Sin, x)), 2);
  int t2 = dag.binary(Op::Div, dag.unary(Op::Exp, y),
                      dag.binary(Op::Add, dag.pow(x, 2), dag.constant(1.0)));
  int t3 = dag.binary(Op::Mul, dag.unary(Op::Atan, dag.binary(Op::Sub, x, y)),
                      dag.unary(Op::Cos, xy));
  int f = dag.binary(Op::Add, dag.binary(Op::Sub, t1, t2), t3);
  ASSERT_EQ(dag.binary(Op::Mul, y, x), xy) << "x*y and y*x must be one node";
  ASSERT_EQ(dag.binary(Op::Add, t2, t1), dag.binary(Op::Add, t1, t2)) << "a+b and b+a: one node";
  ASSERT_NE(dag.binary(Op::Sub, t2, t1), dag.binary(Op::Sub, t1, t2));
  std::vector<int> prog = dag.closure({f});
  Evaluator ev(dag);
  Gen gen(777);
  for (int ibox = 0; ibox < 300; ++ibox) {
    auto [lx, hx] = gen.box(Dom::PowArg);
    auto [ly, hy] = gen.box(Dom::PowArg);
    Box box{Interval(lx, hx), Interval(ly, hy)};
    ASSERT_EQ(ev.forward(prog, box), EvalStatus::Defined);
    for (int s = 0; s < 5; ++s) {
      double px = gen.u(lx, hx), py = gen.u(ly, hy);
      R X(px), Y(py);
      R xyv = X * Y;
      R e;
      mpfr_exp(e.get(), Y.get(), MPFR_RNDN);
      R at;
      mpfr_atan(at.get(), (X - Y).get(), MPFR_RNDN);
      R val = sqr(xyv + sin(X)) - e / (sqr(X) + R(1)) + at * cos(xyv);
      EXPECT_TRUE(aspects_test::interval_contains(ev.value(f), val))
          << "x=" << px << " y=" << py << " f=" << val.str() << " not in "
          << interval_str(ev.value(f));
    }
  }
}

// ---------------------------------------------------------------- decimal literals

// Exact rational value of a decimal literal [sign] digits [. digits] [e [sign] digits].
void decimal_to_mpq(mpq_t q, const std::string& s) {
  size_t i = 0;
  bool neg = false;
  if (s[i] == '+' || s[i] == '-') neg = s[i++] == '-';
  std::string digits;
  long exp10 = 0;
  bool frac = false;
  for (; i < s.size() && s[i] != 'e' && s[i] != 'E'; ++i) {
    if (s[i] == '.') {
      frac = true;
      continue;
    }
    digits += s[i];
    if (frac) --exp10;
  }
  if (i < s.size()) exp10 += std::stol(s.substr(i + 1));
  std::string num = digits, den = "1";
  if (exp10 >= 0)
    num += std::string(size_t(exp10), '0');
  else
    den += std::string(size_t(-exp10), '0');
  std::string text = (neg ? "-" : "") + num + "/" + den;
  ASSERT_EQ(mpq_set_str(q, text.c_str(), 10), 0) << text;
  mpq_canonicalize(q);
}

struct Decimal {
  const char* text;
  bool representable;  // exactly a binary floating-point number at 53 bits
};

TEST(DecimalLiterals, FromStringEnclosesExactValue) {
  const Decimal cases[] = {
      {"0.1", false},        {"15.9", false},          {"0.8822", false},
      {"20.8", false},       {"1e-3", false},          {"123456.789e-2", false},
      {"0.3", false},        {"2.675", false},         {"1e23", false},
      {"-0.1", false},       {"3.14159265358979323846264338327950288", false},
      {"0.5", true},         {"17", true},             {"10", true},
      {"0.125", true},       {"1e2", true},            {"-2.5", true},
      {"0", true},
  };
  for (long prec : {24L, 53L, 113L, 200L}) {
    set_working_precision(prec);
    for (const Decimal& d : cases) {
      SCOPED_TRACE(std::string(d.text) + " at " + std::to_string(prec) + " bits");
      Interval v;
      ASSERT_TRUE(Interval::from_string(v, d.text));
      mpq_t q;
      mpq_init(q);
      decimal_to_mpq(q, d.text);
      mpfr_srcptr lo = &v.get()->left, hi = &v.get()->right;
      EXPECT_LE(mpfr_cmp_q(lo, q), 0) << "left endpoint " << mpfr_str(lo, 40) << " above value";
      EXPECT_GE(mpfr_cmp_q(hi, q), 0) << "right endpoint " << mpfr_str(hi, 40) << " below value";
      EXPECT_EQ(mpfr_get_prec(lo), prec);
      // Exactly representable at this precision iff rounding 1/10-style values is exact.
      mpfr_t tmp;
      mpfr_init2(tmp, prec);
      bool representable = mpfr_set_q(tmp, q, MPFR_RNDN) == 0;
      mpfr_clear(tmp);
      if (prec == 53) {
        EXPECT_EQ(representable, d.representable);
      }
      if (representable) {
        EXPECT_EQ(mpfr_cmp(lo, hi), 0) << "exact literal must give a point interval";
        EXPECT_EQ(mpfr_cmp_q(lo, q), 0);
      } else {
        // Not a binary number: the enclosure is the tightest one, two adjacent floats.
        EXPECT_LT(mpfr_cmp(lo, hi), 0) << "inexact literal collapsed to a point";
        mpfr_t next;
        mpfr_init2(next, prec);
        mpfr_set(next, lo, MPFR_RNDN);
        mpfr_nextabove(next);
        EXPECT_EQ(mpfr_cmp(next, hi), 0) << "enclosure wider than one ulp: " << interval_str(v, 40);
        mpfr_clear(next);
      }
      mpq_clear(q);
    }
  }
  set_working_precision(53);
}

TEST(DecimalLiterals, MalformedTextIsRejected) {
  set_working_precision(53);
  Interval v;
  EXPECT_FALSE(Interval::from_string(v, "abc"));
  EXPECT_FALSE(Interval::from_string(v, ""));
}

// The parser keeps decimal constants as enclosures: "0.1" becomes a non-degenerate
// interval holding 1/10 (never the double 0.1000000000000000055...).
TEST(DecimalLiterals, ParserKeepsDecimalConstantsAsEnclosures) {
  set_working_precision(53);
  Model m = parse_model(
      "robot T\n"
      "pose x in [0.1, 2]\n"
      "command q in [-1, 1]\n"
      "equation x - 0.1*q = 0.3\n",
      "t.robot");
  mpq_t tenth, three_tenths;
  mpq_init(tenth);
  mpq_init(three_tenths);
  decimal_to_mpq(tenth, "0.1");
  decimal_to_mpq(three_tenths, "0.3");

  // Domain lower bound: rounded down, strictly below 1/10.
  const Interval& dom = m.vars[0].domain;
  EXPECT_LT(mpfr_cmp_q(&dom.get()->left, tenth), 0) << interval_str(dom, 30);
  EXPECT_EQ(mpfr_cmp_ui(&dom.get()->right, 2), 0);

  int found_tenth = 0, found_3tenths = 0, double_tenth = 0;
  for (int id = 0; id < m.dag.size(); ++id) {
    if (m.dag.node(id).op != Op::Const) continue;
    const Interval& c = m.dag.constant_value(id);
    mpfr_srcptr lo = &c.get()->left, hi = &c.get()->right;
    if (mpfr_cmp_q(lo, tenth) <= 0 && mpfr_cmp_q(hi, tenth) >= 0 && mpfr_cmp(lo, hi) < 0)
      ++found_tenth;
    if (mpfr_cmp_q(lo, three_tenths) <= 0 && mpfr_cmp_q(hi, three_tenths) >= 0 &&
        mpfr_cmp(lo, hi) < 0)
      ++found_3tenths;
    if (mpfr_cmp_d(lo, 0.1) == 0 && mpfr_cmp_d(hi, 0.1) == 0) ++double_tenth;
  }
  EXPECT_EQ(found_tenth, 1) << "no (or several) non-degenerate constant node enclosing 1/10";
  EXPECT_EQ(found_3tenths, 1) << "no non-degenerate constant node enclosing 3/10";
  EXPECT_EQ(double_tenth, 0) << "0.1 was turned into the double 0.1";

  // Evaluating the equation at the exact solution x = 0.3 + 0.1*q (q = 1: x = 0.4)
  // must give an interval containing 0, but not the point 0 (the constants are wide).
  Evaluator ev(m.dag);
  std::vector<int> prog = m.dag.closure(m.equations);
  Box box{Interval(0.4), Interval(1.0)};
  ASSERT_EQ(ev.forward(prog, box), EvalStatus::Defined);
  const Interval& f = ev.value(m.equations[0]);
  EXPECT_TRUE(f.contains(0.0)) << interval_str(f);
  EXPECT_LT(mpfr_cmp(&f.get()->left, &f.get()->right), 0) << interval_str(f);
  mpq_clear(tenth);
  mpq_clear(three_tenths);
}

// ---------------------------------------------------------------- Interval basics

TEST(IntervalBasics, DirectedConversionsToDouble) {
  for (long prec : {24L, 53L, 113L}) {
    set_working_precision(prec);
    SCOPED_TRACE(prec);
    for (const char* text : {"0.1", "-0.1", "15.9", "1e-300", "123456.789e-2", "2", "-0.5"}) {
      Interval v;
      ASSERT_TRUE(Interval::from_string(v, text));
      double lo = v.lo_down(), hi = v.hi_up();
      EXPECT_GE(mpfr_cmp_d(&v.get()->left, lo), 0) << text;
      EXPECT_LE(mpfr_cmp_d(&v.get()->right, hi), 0) << text;
      // Tight: the next double inward is beyond the endpoint.
      EXPECT_LT(mpfr_cmp_d(&v.get()->left, std::nextafter(lo, INFINITY)), 0) << text;
      EXPECT_GT(mpfr_cmp_d(&v.get()->right, std::nextafter(hi, -INFINITY)), 0) << text;
      double m = v.mid();
      EXPECT_TRUE(lo <= m && m <= hi) << text;
      // width_up is an upper bound of the exact width.
      mpfr_t w;
      mpfr_init2(w, 4 * prec);
      mpfr_sub(w, &v.get()->right, &v.get()->left, MPFR_RNDU);
      EXPECT_LE(mpfr_cmp_d(w, v.width_up()), 0) << text;
      mpfr_clear(w);
    }
  }
  set_working_precision(53);
}

// lo_down/hi_up read numbers of at most 53 bits straight off the limb. Against MPFR's own
// directed conversion on random ends of every exponent a double has and beyond (subnormal,
// overflowing), zeros of both signs, infinities, and precisions on both sides of 53.
// Seen failing with the exponent off by one and with the sign bit dropped.
TEST(IntervalBasics, EndsReadOffTheLimbEqualMpfrGetD) {
  std::mt19937_64 g(53);
  int fast = 0;
  for (long prec : {2L, 24L, 52L, 53L, 54L, 64L, 113L}) {
    set_working_precision(prec);
    for (int trial = 0; trial < 20000; ++trial) {
      Interval v;
      mpfr_t a, b;
      mpfr_inits2(prec, a, b, (mpfr_ptr)nullptr);
      double x = std::ldexp(double(g() >> 11) / 9007199254740992.0 + 0.5, int(g() % 2200) - 1100);
      double y = x * (1 + double(g() % 1000) / 1e4);
      if (g() % 2) x = -x;
      mpfr_set_d(a, std::min(x, y), MPFR_RNDD);
      mpfr_set_d(b, std::max(x, y), MPFR_RNDU);
      switch (trial % 50) {
        case 0: mpfr_set_zero(a, -1); break;
        case 1: mpfr_set_zero(b, -1); mpfr_set_zero(a, 1); break;
        case 2: mpfr_set_inf(a, -1); break;
        case 3: mpfr_set_inf(b, 1); break;
        case 4: mpfr_set_ui_2exp(b, 1, 1024, MPFR_RNDU); break;   // just beyond DBL_MAX
        case 5: mpfr_set_si_2exp(a, -1, -1022, MPFR_RNDD); break; // smallest normal
      }
      mpfi_interv_fr(v.get(), a, b);
      fast += std::isnormal(v.lo_down());
      double lo = mpfr_get_d(&v.get()->left, MPFR_RNDD) + 0.0;
      double hi = mpfr_get_d(&v.get()->right, MPFR_RNDU) + 0.0;
      double l = v.lo_down(), h = v.hi_up();
      ASSERT_EQ(std::memcmp(&lo, &l, 8), 0) << prec << " " << lo << " " << l;  // sign of 0 too
      ASSERT_EQ(std::memcmp(&hi, &h, 8), 0) << prec << " " << hi << " " << h;
      mpfr_clears(a, b, (mpfr_ptr)nullptr);
    }
  }
  EXPECT_GT(fast, 50000);
  set_working_precision(53);
}

TEST(IntervalBasics, SetOperations) {
  set_working_precision(53);
  Interval a(1.0, 3.0), b(2.0, 5.0), c(4.0, 6.0), p(3.0);
  EXPECT_TRUE(a.overlaps(b));
  EXPECT_FALSE(a.overlaps(c));
  EXPECT_TRUE(a.overlaps(p));   // closed: touching at 3
  EXPECT_TRUE(p.overlaps(a));
  EXPECT_TRUE(a.contains(p));
  EXPECT_FALSE(a.strictly_contains(p));  // 3 is an endpoint
  EXPECT_TRUE(a.strictly_contains(Interval(1.5, 2.5)));
  EXPECT_TRUE(a.contains(1.0));
  EXPECT_FALSE(a.contains(3.0000000000000004));
  Interval i = a;
  ASSERT_TRUE(i.intersect(b));
  EXPECT_EQ(i.lo_down(), 2.0);
  EXPECT_EQ(i.hi_up(), 3.0);
  Interval j = a;
  EXPECT_FALSE(j.intersect(c));
  EXPECT_TRUE(j.empty());
  Interval e;
  e.set_entire();
  EXPECT_FALSE(e.bounded());
  EXPECT_TRUE(e.contains(1e308));
  EXPECT_EQ(e.mid(), 0.0);
  Interval h;
  h.set_hull(-2.0, 7.0);
  EXPECT_EQ(h.lo_down(), -2.0);
  EXPECT_EQ(h.hi_up(), 7.0);
  EXPECT_EQ(h.width_up(), 9.0);
  EXPECT_EQ(certain_sign(Interval(0.5, 1.0)), 1);
  EXPECT_EQ(certain_sign(Interval(-1.0, -0.5)), -1);
  EXPECT_EQ(certain_sign(Interval(0.0, 1.0)), 0);
  EXPECT_EQ(Interval(1.0, 2.5).str(), "[1, 2.5]");
  EXPECT_EQ(box_width(Box{Interval(0.0, 1.0), Interval(-4.0, 0.0), Interval(2.0)}), 4.0);
}

TEST(IntervalBasics, CopiesKeepTheirPrecision) {
  set_working_precision(200);
  Interval v;
  ASSERT_TRUE(Interval::from_string(v, "0.1"));
  set_working_precision(53);
  Interval copy(v);
  EXPECT_EQ(mpfi_get_prec(copy.get()), 200);
  Interval moved(std::move(copy));
  EXPECT_EQ(mpfi_get_prec(moved.get()), 200);
  EXPECT_TRUE(mpfr_equal_p(&moved.get()->left, &v.get()->left));
  EXPECT_TRUE(mpfr_equal_p(&moved.get()->right, &v.get()->right));
  // Assigning into a 53-bit interval rounds outward: still encloses 1/10.
  Interval low(0.0);
  low = v;
  EXPECT_EQ(mpfi_get_prec(low.get()), 53);
  EXPECT_LE(mpfr_cmp(&low.get()->left, &v.get()->left), 0);
  EXPECT_GE(mpfr_cmp(&low.get()->right, &v.get()->right), 0);
}

// Hash-consing of constants must not merge two different enclosures, at any precision.
TEST(DagConstants, DistinctConstantsStayDistinctAtHighPrecision) {
  for (long prec : {53L, 200L, 1024L}) {
    set_working_precision(prec);
    SCOPED_TRACE("precision " + std::to_string(prec));
    Interval third;
    mpfi_set_ui(third.get(), 1);
    mpfi_div_ui(third.get(), third.get(), 3);  // [1/3 rounded down, 1/3 rounded up]
    // A point interval at the left endpoint of 1/3: a different constant.
    Interval lo_pt;
    mpfi_set_fr(lo_pt.get(), &third.get()->left);
    Dag dag;
    int a = dag.constant(third);
    int b = dag.constant(lo_pt);
    EXPECT_NE(a, b) << "the constants [RNDD(1/3), RNDU(1/3)] (width one ulp) and the point "
                       "[RNDD(1/3), RNDD(1/3)] were merged into one node";
    EXPECT_TRUE(mpfr_equal_p(&dag.constant_value(b).get()->left, &lo_pt.get()->left));
    EXPECT_TRUE(mpfr_equal_p(&dag.constant_value(b).get()->right, &lo_pt.get()->right))
        << "node " << b << " holds " << interval_str(dag.constant_value(b), 40);
    EXPECT_EQ(mpfr_cmp(&dag.constant_value(a).get()->right, &third.get()->right), 0)
        << "node " << a << " holds " << interval_str(dag.constant_value(a), 40);
    EXPECT_EQ(dag.constant(third), a) << "identical constants must share a node";
    // The other insertion order: the node returned for 1/3 must still enclose 1/3.
    Dag dag2;
    dag2.constant(lo_pt);
    int c = dag2.constant(third);
    mpq_t q;
    mpq_init(q);
    mpq_set_ui(q, 1, 3);
    EXPECT_LT(mpfr_cmp_q(&dag2.constant_value(c).get()->left, q), 0);
    EXPECT_GT(mpfr_cmp_q(&dag2.constant_value(c).get()->right, q), 0)
        << "unsound: the constant node for [RNDD(1/3), RNDU(1/3)] holds the point RNDD(1/3), "
           "which excludes 1/3";
    mpq_clear(q);
  }
  set_working_precision(53);
}

}  // namespace
