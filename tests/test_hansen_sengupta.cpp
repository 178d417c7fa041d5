// P1 alone (proofs/hansen_sengupta.*): the parametric Hansen–Sengupta operator and
// iteration (9) against roots known exactly (MPFR at 256 bits):
//  - a box with a unique root: when proved, the image holds the root at sampled poses;
//  - a box with no root: the contracting operator refutes it; iteration (9), which does
//    not intersect, may only prove a root outside it (and then holds that root);
//  - a box with two roots, or a singular Jacobian at the root: never proved;
//  - a box the operator refutes holds no root (refutation is sound).
//
// Seen failing (each break made in proofs/hansen_sengupta.cpp, then reverted):
//  - prove_existence with `if (inside)` replaced by `if (true)`: NoRootIsNeverClaimed and
//    RandomBoxesAgreeWithTheExactRoots fail;
//  - `d_sub(y[i], qmid[i], w.t2)` replaced by `y[i] = w.t2; add_d(...)` (Newton
//    step of the wrong sign): UniqueRootIsInTheImage, UniqueRootOfA2x2SystemIsInTheImage
//    and RandomBoxesAgreeWithTheExactRoots fail;
//  - Fq evaluated on ws.mid_box instead of the box (no mean-value form): the two
//    UniqueRoot tests, NoRootIsNeverClaimed and SingularJacobianIsNeverProved fail;
//  - the (C·Fq)_ii ∋ 0 and unbounded-image guards removed and strictly_contains replaced
//    by overlaps: TwoRootsAreNeverProved, SingularJacobianIsNeverProved,
//    NoRootIsNeverClaimed and RandomBoxesAgreeWithTheExactRoots fail.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "hansen_sengupta.h"
#include "model/model.h"
#include "model/model_eval.h"
#include "robot_refs.h"
#include "test_util.h"

using namespace aspects;
using aspects_test::interval_contains;
using aspects_test::interval_str;
using aspects_test::R;

namespace {

// q^2 = x: for x in [1, 2] the roots are ±sqrt(x).
const char* const kSqrtModel =
    "robot Sqrt\n"
    "pose x in [0, 2]\n"
    "command q in [-3, 3]\n"
    "equation q^2 - x = 0\n";

// q1^2 + q2^2 = x1, q1 - q2 = x2: roots q2 = (-x2 ± sqrt(2 x1 - x2^2)) / 2, q1 = q2 + x2.
const char* const kCircleLineModel =
    "robot CircleLine\n"
    "pose x1 in [1, 2]\n"
    "pose x2 in [0, 1]\n"
    "command q1 in [-3, 3]\n"
    "command q2 in [-3, 3]\n"
    "equation q1^2 + q2^2 - x1 = 0\n"
    "equation q1 - q2 - x2 = 0\n";

// q^3 = x at x = 0: one root, q = 0, where Fq = 3q^2 vanishes.
const char* const kCubeModel =
    "robot Cube\n"
    "pose x in [0, 0]\n"
    "command q in [-1, 1]\n"
    "equation q^3 - x = 0\n";

// Two copies of one equation: Fq is singular everywhere (a line of roots).
const char* const kDoubledModel =
    "robot Doubled\n"
    "pose x1 in [0, 1]\n"
    "pose x2 in [0, 1]\n"
    "command q1 in [-3, 3]\n"
    "command q2 in [-3, 3]\n"
    "equation q1 + q2 - x1 = 0\n"
    "equation 2*q1 + 2*q2 - 2*x1 = 0\n";

class HansenSengupta : public ::testing::Test {
 protected:
  void SetUp() override {
    set_working_precision(53);
    aspects_test::ref_prec() = 256;
  }
};

Box box1(double xlo, double xhi, double qlo, double qhi) {
  return {Interval(xlo, xhi), Interval(qlo, qhi)};
}

// The exact positive root of q^2 = x.
R sqrt_root(double x) { return sqrt(R(x)); }

bool prove(ModelEvaluator& ev, const Box& box, double tau, int iterations, ExistenceProof& p) {
  HsWorkspace ws;
  return prove_existence(ev, box, tau, iterations, p, ws) == Existence::Proved;
}

// n doubles spread over [lo, hi], both ends included.
std::vector<double> samples(double lo, double hi, int n) {
  std::vector<double> s;
  for (int i = 0; i <= n; ++i) s.push_back(i == n ? hi : lo + (hi - lo) * i / n);
  return s;
}

}  // namespace

TEST_F(HansenSengupta, UniqueRootIsInTheImage) {
  Model m = parse_model(kSqrtModel, "sqrt");
  ModelEvaluator ev(m);
  Box box = box1(1.0, 1.1, 0.9, 1.2);  // sqrt([1, 1.1]) ⊂ [1, 1.0489]
  ExistenceProof p;
  ASSERT_TRUE(prove(ev, box, 1.01, 8, p));
  for (double x : samples(1.0, 1.1, 16)) {
    R root = sqrt_root(x);
    EXPECT_TRUE(interval_contains(p.image[0], root)) << x << " " << interval_str(p.image[0]);
    EXPECT_TRUE(interval_contains(p.inflated[0], root));
    EXPECT_FALSE(interval_contains(p.inflated[0], -root));  // the other root is outside
  }
  EXPECT_TRUE(p.inflated[0].strictly_contains(p.image[0]));
}

TEST_F(HansenSengupta, UniqueRootOfA2x2SystemIsInTheImage) {
  Model m = parse_model(kCircleLineModel, "circle-line");
  ModelEvaluator ev(m);
  // x1 ∈ [1.5, 1.52], x2 ∈ [0.2, 0.21]: q2 ≈ 0.77, q1 ≈ 0.97 (the + branch only).
  Box box = {Interval(1.5, 1.52), Interval(0.2, 0.21), Interval(0.85, 1.1), Interval(0.65, 0.9)};
  ExistenceProof p;
  ASSERT_TRUE(prove(ev, box, 1.01, 8, p));
  for (double x1 : samples(1.5, 1.52, 6))
    for (double x2 : samples(0.2, 0.21, 6)) {
      R d = sqrt(R(2) * R(x1) - sqr(R(x2)));
      R q2 = (d - R(x2)) / R(2), q1 = q2 + R(x2);
      EXPECT_TRUE(interval_contains(p.image[0], q1)) << q1.str() << interval_str(p.image[0]);
      EXPECT_TRUE(interval_contains(p.image[1], q2)) << q2.str() << interval_str(p.image[1]);
    }
}

TEST_F(HansenSengupta, NoRootIsRefuted) {
  Model m = parse_model(kSqrtModel, "sqrt");
  ModelEvaluator ev(m);
  Box box = box1(1.0, 2.0, 1.6, 2.0);
  ASSERT_TRUE(sqrt_root(2.0) < R(1.6));  // exact: no x ∈ [1, 2] has its root in [q]
  HsWorkspace ws;
  std::vector<Interval> image;
  EXPECT_EQ(hansen_sengupta(ev, box, true, image, ws), HsStatus::NoSolution);
}

// Iteration (9) does not intersect with the box: from a box without a root it may drift
// to a root outside it and prove that one. It must never claim a root that is not there.
TEST_F(HansenSengupta, NoRootIsNeverClaimed) {
  Model m = parse_model(kSqrtModel, "sqrt");
  ModelEvaluator ev(m);
  int proved = 0;
  for (double tau : {1.0, 1.01, 1.5, 3.0})
    for (const Box& box : {box1(1.0, 2.0, 1.6, 2.0), box1(1.0, 2.0, -0.5, 0.5)}) {
      ExistenceProof p;
      if (!prove(ev, box, tau, 30, p)) continue;
      ++proved;
      for (double x : samples(1.0, 2.0, 8)) {
        R root = sqrt_root(x);
        bool pos = interval_contains(p.image[0], root), neg = interval_contains(p.image[0], -root);
        EXPECT_NE(pos, neg) << tau << " " << x << " " << interval_str(p.image[0]);
        EXPECT_FALSE(box[1].contains(p.image[0])) << tau;  // the root found is outside [q]
      }
    }
  EXPECT_LE(proved, 8);
}

TEST_F(HansenSengupta, TwoRootsAreNeverProved) {
  Model m = parse_model(kSqrtModel, "sqrt");
  ModelEvaluator ev(m);
  Model m2 = parse_model(kCircleLineModel, "circle-line");
  ModelEvaluator ev2(m2);
  // Both branches of the circle meet the line inside [-2, 2]^2.
  Box both = {Interval(1.5, 1.52), Interval(0.2, 0.21), Interval(-2, 2), Interval(-2, 2)};
  for (double tau : {1.0, 1.01, 1.5, 3.0}) {
    ExistenceProof p;
    EXPECT_FALSE(prove(ev, box1(1.0, 1.1, -1.5, 1.5), tau, 30, p)) << tau;  // ±sqrt(x)
    EXPECT_FALSE(prove(ev, box1(1.0, 1.1, -1.2, 1.1), tau, 30, p)) << tau;  // off centre
    EXPECT_FALSE(prove(ev2, both, tau, 30, p)) << tau;
  }
}

TEST_F(HansenSengupta, SingularJacobianIsNeverProved) {
  Model cube = parse_model(kCubeModel, "cube");
  ModelEvaluator ev(cube);
  Model doubled = parse_model(kDoubledModel, "doubled");
  ModelEvaluator ev2(doubled);
  Box line = {Interval(0.5), Interval(0.25), Interval(0, 1), Interval(-0.5, 1)};
  for (double tau : {1.0, 1.01, 1.5}) {
    ExistenceProof p;
    // The unique root q = 0 is a triple root: Fq(0) = 0.
    EXPECT_FALSE(prove(ev, {Interval(0.0), Interval(-0.1, 0.2)}, tau, 30, p)) << tau;
    EXPECT_FALSE(prove(ev2, line, tau, 30, p)) << tau;
  }
  HsWorkspace ws;
  std::vector<Interval> image;
  EXPECT_EQ(hansen_sengupta(ev2, line, true, image, ws), HsStatus::Failed);
}

// The failure's kind, for the bisector: on q^2 = x with [q] = [0.9, 1.2] holding the one
// root of every x ∈ [1, 1.1], a pose [1, 9] spreads the root over [1, 3], more than the
// 4 times [q] that iteration (9) may grow to (PoseSpread); at a point pose the two roots ±1 of [q] = [-1.5, 1.5] block it
// (NotProved: a narrower pose cannot help). Break it to see it fail: make pose_spreads()
// compare w(b_i) with 20 times the box (the first case fails).
TEST_F(HansenSengupta, FailureSaysWhetherThePoseSpreadBlockedIt) {
  Model m = parse_model(kSqrtModel, "sqrt");
  ModelEvaluator ev(m);
  HsWorkspace ws;
  ExistenceProof p;
  EXPECT_EQ(prove_existence(ev, box1(1.0, 9.0, 0.9, 1.2), 1.01, 8, p, ws), Existence::PoseSpread);
  EXPECT_EQ(prove_existence(ev, box1(1.0, 1.1, 0.9, 1.2), 1.01, 8, p, ws), Existence::Proved);
  EXPECT_EQ(prove_existence(ev, box1(1.0, 1.0, -1.5, 1.5), 1.01, 8, p, ws),
            Existence::NotProved);
}

// Random boxes of q^2 = x: the exact roots decide what each outcome may be.
TEST_F(HansenSengupta, RandomBoxesAgreeWithTheExactRoots) {
  Model m = parse_model(kSqrtModel, "sqrt");
  ModelEvaluator ev(m);
  std::mt19937 g(14);
  int proved = 0, refuted = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    double xlo = aspects_test::uniform(g, 0.05, 1.9);
    double xhi = xlo + aspects_test::uniform(g, 0, 0.1);
    double c = aspects_test::uniform(g, -1.6, 1.6), r = aspects_test::uniform(g, 1e-3, 0.5);
    Box box = box1(xlo, xhi, c - r, c + r);
    const Interval& q = box[1];
    // sqrt is increasing: the roots ±sqrt(x), x ∈ [x], sweep ±[sqrt xlo, sqrt xhi].
    R lo = sqrt_root(xlo), hi = sqrt_root(xhi);
    R qlo(q.lo_down()), qhi(q.hi_up());
    bool pos_root = !(hi < qlo || qhi < lo), neg_root = !(-lo < qlo || qhi < -hi);
    HsWorkspace ws;
    std::vector<Interval> image;
    HsStatus s = hansen_sengupta(ev, box, true, image, ws);
    if (s == HsStatus::NoSolution) {
      ++refuted;
      EXPECT_FALSE(pos_root || neg_root) << interval_str(box[0]) << interval_str(q);
    }
    ExistenceProof p;
    if (!prove(ev, box, 1.01, 12, p)) continue;
    ++proved;
    // Proved: for each sampled x exactly one root in the inflated iterate, and in the image.
    for (double x : samples(xlo, xhi, 4)) {
      R root = sqrt_root(x);
      bool in_pos = interval_contains(p.inflated[0], root);
      bool in_neg = interval_contains(p.inflated[0], -root);
      EXPECT_NE(in_pos, in_neg) << interval_str(box[0]) << interval_str(q);
      EXPECT_TRUE(interval_contains(p.image[0], in_pos ? root : -root));
    }
  }
  EXPECT_GT(proved, 100);  // not vacuous
  EXPECT_GT(refuted, 100);
}

// The roles swapped (in_pose): q^2 - x = 0 at the point command q = 1.5 has the one pose
// x = 2.25, proved in x with Fx = −1; a pose box without it is never proved.
TEST_F(HansenSengupta, InPoseProvesThePoseOfAPointCommand) {
  Model m = parse_model(
      "robot SqrtWide\npose x in [0, 4]\ncommand q in [-3, 3]\nequation q^2 - x = 0\n", "w");
  ModelEvaluator ev(m);
  HsWorkspace ws;
  ExistenceProof p;
  ASSERT_EQ(prove_existence(ev, box1(2, 2.5, 1.5, 1.5), 1.01, 8, p, ws, true), Existence::Proved);
  EXPECT_TRUE(p.image[0].contains(Interval(2.25, 2.25)));
  EXPECT_TRUE(p.inflated[0].strictly_contains(p.image[0]));
  EXPECT_NE(prove_existence(ev, box1(2.5, 3, 1.5, 1.5), 1.01, 8, p, ws, true), Existence::Proved);
  // The command version on the same box refuses: the command is a point, not a box of q.
  EXPECT_NE(prove_existence(ev, box1(2, 2.5, 1.5, 1.5), 1.01, 8, p, ws), Existence::Proved);
}

// At 53 bits the sweep runs on doubles: on boxes around points of the robots' surfaces
// (robot_refs.h) it must give MPFI's status, preconditioner and image end for end, and
// the existence proofs must agree.
TEST_F(HansenSengupta, DoublesGiveMpfisSweepOnTheRobots) {
  int compared = 0, proved = 0;
  std::mt19937 g(99);
  std::uniform_real_distribution<double> U(0, 1);
  for (const aspects_test::RobotRef& ref : aspects_test::robot_refs()) {
    std::ifstream in(ref.path());
    std::stringstream text;
    text << in.rdbuf();
    Model m = parse_model(text.str(), ref.path());
    ModelEvaluator ev(m), em(m, Arithmetic::MpfiOnly);
    HsWorkspace wd, wm;
    for (int trial = 0; trial < 100; ++trial) {
      const aspects_test::Point p = ref.solution(g);
      Box box(p.size());
      for (size_t v = 0; v < p.size(); ++v) {
        double c = p[v].d(), w = std::ldexp(1.0, -2 - int(U(g) * 14));
        box[v].set_hull(c - w * U(g), c + w * U(g));
      }
      std::vector<Interval> yd, ym;
      for (bool intersect : {false, true}) {
        HsStatus sd = hansen_sengupta(ev, box, intersect, yd, wd);
        HsStatus sm = hansen_sengupta(em, box, intersect, ym, wm);
        ASSERT_TRUE(wd.in_doubles);
        ASSERT_FALSE(wm.in_doubles);
        ASSERT_EQ(sd, sm) << ref.file << " trial " << trial;
        if (sd != HsStatus::Ok) continue;
        ++compared;
        ASSERT_EQ(wd.C, wm.C);
        for (size_t j = 0; j < yd.size(); ++j) {
          ASSERT_EQ(yd[j].lo_down(), ym[j].lo_down()) << ref.file << " trial " << trial;
          ASSERT_EQ(yd[j].hi_up(), ym[j].hi_up()) << ref.file << " trial " << trial;
        }
      }
      ExistenceProof pd, pm;
      Existence ed = prove_existence(ev, box, 1.01, 8, pd, wd);
      ASSERT_EQ(ed, prove_existence(em, box, 1.01, 8, pm, wm))
          << ref.file << " trial " << trial;
      if (ed == Existence::Proved) {
        ++proved;
        ASSERT_EQ(pd.iterations, pm.iterations);
        for (size_t j = 0; j < pd.image.size(); ++j)
          ASSERT_EQ(pd.image[j].hi_up(), pm.image[j].hi_up());
      }
    }
  }
  EXPECT_GT(compared, 200);  // not vacuous
  EXPECT_GT(proved, 50);
}
