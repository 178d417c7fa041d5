// Independent soundness check of the engine's claims, reusing none of its proofs: the
// equations are the hand-written MPFR versions of robot_refs.h, Newton's method runs in
// MPFR at 256 bits with a finite-difference Jacobian, determinants are computed from it.
//  - every (sampled) solution box: for sample poses x in [x], Newton from mid [q] finds
//    a root of f(x, ·) inside [q] (P1), and det Fx, det Fq there are nonzero with the
//    same signs for every sample of every box of one CSNC (P2 and the CSNC claim);
//  - every (sampled) certified link: at its witness pose, the root lies in both boxes
//    (P3), modulo 2π on periodic variables.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "generalized_aspects.h"
#include "robot_refs.h"

using namespace aspects;
using aspects_test::Point;
using aspects_test::R;
using aspects_test::RobotRef;

namespace {

using Matrix = std::vector<std::vector<R>>;

bool is_zero(const R& v) { return !(v < R(0)) && !(v > R(0)); }

// Central differences at h = 2^-100: the error O(h^2) is far below what the signs need.
Matrix jacobian(const RobotRef& ref, const Point& p, const std::vector<int>& cols) {
  R h(std::ldexp(1.0, -100));
  Matrix J(ref.n, std::vector<R>(cols.size()));
  for (size_t c = 0; c < cols.size(); ++c) {
    Point a = p, b = p;
    a[cols[c]] = a[cols[c]] + h;
    b[cols[c]] = b[cols[c]] - h;
    auto fa = ref.f(a), fb = ref.f(b);
    for (int i = 0; i < ref.n; ++i) J[i][c] = (fa[i] - fb[i]) / (R(2) * h);
  }
  return J;
}

// Determinant by Gaussian elimination with partial pivoting; also solves J d = rhs.
R eliminate(Matrix J, std::vector<R>* rhs) {
  int n = int(J.size());
  R det(1);
  for (int k = 0; k < n; ++k) {
    int piv = k;
    for (int i = k + 1; i < n; ++i)
      if (abs(J[i][k]) > abs(J[piv][k])) piv = i;
    if (piv != k) {
      std::swap(J[piv], J[k]);
      if (rhs) std::swap((*rhs)[piv], (*rhs)[k]);
      det = -det;
    }
    det = det * J[k][k];
    if (is_zero(J[k][k])) return R(0);
    for (int i = k + 1; i < n; ++i) {
      R m = J[i][k] / J[k][k];
      for (int j = k; j < n; ++j) J[i][j] = J[i][j] - m * J[k][j];
      if (rhs) (*rhs)[i] = (*rhs)[i] - m * (*rhs)[k];
    }
  }
  if (rhs)
    for (int k = n - 1; k >= 0; --k) {
      R s = (*rhs)[k];
      for (int j = k + 1; j < n; ++j) s = s - J[k][j] * (*rhs)[j];
      (*rhs)[k] = s / J[k][k];
    }
  return det;
}

// Newton on f(x, ·) = 0 from p's command part; true when |f| < 2^-150.
bool newton(const RobotRef& ref, const Model& m, Point& p) {
  for (int it = 0; it < 60; ++it) {
    std::vector<R> f = ref.f(p);
    R norm(0);
    for (auto& v : f) norm = norm + abs(v);
    if (norm < R(std::ldexp(1.0, -150))) return true;
    Matrix J = jacobian(ref, p, m.command);
    std::vector<R> d = f;
    if (is_zero(eliminate(J, &d))) return false;
    for (int j = 0; j < ref.n; ++j) p[m.command[j]] = p[m.command[j]] - d[j];
  }
  return false;
}

bool inside(double lo, double hi, const R& v) { return R(lo) <= v && v <= R(hi); }

struct Case {
  const char* file;
  double eps;
  int max_boxes;  // solution boxes sampled (deterministic stride)
  int max_links;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.file << " eps " << c.eps; }

class IndependentSoundness : public ::testing::TestWithParam<Case> {};

TEST_P(IndependentSoundness, ClaimsHoldAtSampledPoints) {
  const Case c = GetParam();
  RobotRef ref;
  for (auto& r : aspects_test::robot_refs())
    if (r.file == c.file) ref = r;
  ASSERT_EQ(ref.file, c.file);
  set_working_precision(53);
  Model m = load_model(ref.path());
  AspectsConfig cfg;
  cfg.eps = c.eps;
  AspectsResult r = compute_aspects(m, cfg);
  ASSERT_GT(r.solutions, 0);
  const int nv = r.boxes.nv();
  std::mt19937 gen(12345);

  std::vector<int> sol;
  for (int b = 0; b < r.boxes.size(); ++b)
    if (r.boxes.certified(b)) sol.push_back(b);
  size_t stride = std::max<size_t>(1, sol.size() / c.max_boxes);
  std::map<int, std::pair<int, int>> csnc_signs;  // csnc -> (sign det Fx, sign det Fq)
  int checked = 0;
  for (size_t i = 0; i < sol.size(); i += stride) {
    int b = sol[i];
    for (int s = 0; s < 3; ++s) {
      Point p(nv);
      for (int v = 0; v < nv; ++v) {
        double lo = r.boxes.lo(b, v), hi = r.boxes.hi(b, v);
        bool pose = m.vars[v].kind == VarKind::Pose;
        double t = pose ? (s == 0 ? 0.5 : aspects_test::uniform(gen, 0, 1)) : 0.5;
        p[v] = R(lo) + (R(hi) - R(lo)) * R(t);
      }
      ASSERT_TRUE(newton(ref, m, p)) << "box " << b << ": Newton did not converge";
      for (int j : m.command)
        ASSERT_TRUE(inside(r.boxes.lo(b, j), r.boxes.hi(b, j), p[j]))
            << "box " << b << ": root of f(x,.) outside [q] for variable " << m.vars[j].name;
      R dx = eliminate(jacobian(ref, p, m.pose), nullptr);
      R dq = eliminate(jacobian(ref, p, m.command), nullptr);
      ASSERT_FALSE(is_zero(dx));
      ASSERT_FALSE(is_zero(dq));
      std::pair<int, int> sg{dx > R(0) ? 1 : -1, dq > R(0) ? 1 : -1};
      auto it = csnc_signs.emplace(r.csnc[b], sg).first;
      ASSERT_EQ(it->second, sg) << "box " << b << " of CSNC " << r.csnc[b]
                                << ": determinant signs differ within one CSNC";
      ++checked;
    }
  }
  EXPECT_GE(checked, 3);

  ASSERT_EQ(r.link_proofs.size(), r.certified_links.size());
  size_t lstride = std::max<size_t>(1, r.certified_links.size() / c.max_links);
  R two_pi = R(2) * R::pi();
  for (size_t i = 0; i < r.certified_links.size(); i += lstride) {
    const NeighborPair& e = r.neighbors[r.certified_links[i]];
    const LinkRecords& lp = r.link_proofs;
    Point p(nv);
    for (int j = 0; j < m.n(); ++j) p[m.pose[j]] = R(lp.witness(i)[j]);
    for (int j = 0; j < m.n(); ++j)
      p[m.command[j]] = (R(lp.inflated_lo(i, j)) + R(lp.inflated_hi(i, j))) / R(2);
    ASSERT_TRUE(newton(ref, m, p)) << "link " << e.a << "-" << e.b;
    for (int v = 0; v < nv; ++v) {
      ASSERT_TRUE(inside(r.boxes.lo(e.a, v), r.boxes.hi(e.a, v), p[v]))
          << "link " << e.a << "-" << e.b << ": point leaves box " << e.a;
      R shifted = p[v] - two_pi * R(e.shift(v));
      ASSERT_TRUE(inside(r.boxes.lo(e.b, v), r.boxes.hi(e.b, v), shifted))
          << "link " << e.a << "-" << e.b << ": point leaves box " << e.b;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Robots, IndependentSoundness,
                         ::testing::Values(Case{"prrp.robot", 0.1, 100000, 100000},
                                           Case{"rprpr.robot", 0.1, 100000, 100000},
                                           Case{"rrrrr.robot", 0.3, 1500, 1500},
                                           Case{"3rpr.robot", 3.0, 1000, 1000},
                                           Case{"3rrr_star.robot", 1.0, 600, 600}),
                         [](const auto& info) {
                           std::string s = info.param.file;
                           return s.substr(0, s.find('.'));
                         });

}  // namespace
