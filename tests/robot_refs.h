// Independent high-precision (MPFR) versions of the five robot models of robots/, for
// the HC4 and Jacobian tests: the equations written by hand from the .robot files (with
// the exact decimal constants), and samplers of exact-to-~2^-250 points of the
// constraint surface inside the declared domains.
#pragma once

#include <functional>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "test_util.h"

#ifndef ASPECTS_ROBOTS_DIR
#error "ASPECTS_ROBOTS_DIR must be defined (path of robots/)"
#endif

namespace aspects_test {

using Point = std::vector<R>;  // model order (declaration order of the .robot file)

struct RobotRef {
  std::string file;                 // under robots/
  std::string name;                 // `robot` statement
  std::vector<std::string> vars;    // model order
  int n;
  std::function<std::vector<R>(const Point&)> f;  // residuals lhs - rhs
  std::function<Point(std::mt19937&)> solution;   // a point with f = 0, inside the domain

  std::string path() const { return std::string(ASPECTS_ROBOTS_DIR) + "/" + file; }
};

// Rotate an angle into (-pi, pi].
inline R wrap_angle(R a) {
  R pi = R::pi(), two_pi = R(2) * R::pi();
  while (a > pi) a = a - two_pi;
  while (a <= -pi) a = a + two_pi;
  return a;
}

// Angle q with |A - rho*(cos q, sin q)| = rho (both circles of radius rho), choosing
// one of the two solutions; false when |A| > 2 rho or A = 0.
inline bool circle_angle(const R& ax, const R& ay, double rho, bool plus, R& q) {
  R na = sqrt(sqr(ax) + sqr(ay));
  if (!(na > R(1e-6)) || na > R(2 * rho) - R(1e-9)) return false;
  R delta = acos(na / R(2 * rho));
  q = wrap_angle(atan2(ay, ax) + (plus ? delta : -delta));
  return true;
}

inline void PrintTo(const RobotRef& r, std::ostream* os) { *os << r.file; }

inline std::vector<RobotRef> robot_refs() {
  std::vector<RobotRef> v;

  // ------------------------------------------------------------------ PRRP
  {
    RobotRef r;
    r.file = "prrp.robot";
    r.name = "PRRP";
    r.vars = {"x", "q"};
    r.n = 1;
    r.f = [](const Point& p) { return std::vector<R>{sqr(p[0]) + sqr(p[1]) - R(1)}; };
    r.solution = [](std::mt19937& g) {
      R t(uniform(g, -3.14159, 3.14159));
      return Point{cos(t), sin(t)};
    };
    v.push_back(r);
  }

  // ------------------------------------------------------------------ RPRPR
  {
    RobotRef r;
    r.file = "rprpr.robot";
    r.name = "RPRPR";
    r.vars = {"x1", "x2", "q1", "q2"};
    r.n = 2;
    r.f = [](const Point& p) {
      return std::vector<R>{sqr(p[0]) + sqr(p[1]) - sqr(p[2]),
                            sqr(p[0] - R(9)) + sqr(p[1]) - sqr(p[3])};
    };
    r.solution = [](std::mt19937& g) {
      for (;;) {
        R x1(uniform(g, -6, 6)), x2(uniform(g, -6, 6));
        R q1 = sqrt(sqr(x1) + sqr(x2)), q2 = sqrt(sqr(x1 - R(9)) + sqr(x2));
        if (q1 >= R(2) && q1 <= R(6) && q2 >= R(4) && q2 <= R(9)) return Point{x1, x2, q1, q2};
      }
    };
    v.push_back(r);
  }

  // ------------------------------------------------------------------ RRRRR
  {
    RobotRef r;
    r.file = "rrrrr.robot";
    r.name = "RRRRR";
    r.vars = {"x1", "x2", "q1", "q2"};
    r.n = 2;
    r.f = [](const Point& p) {
      const R &x1 = p[0], &x2 = p[1], &q1 = p[2], &q2 = p[3];
      return std::vector<R>{
          sqr(x1 - R(8) * cos(q1)) + sqr(x2 - R(8) * sin(q1)) - R(25),
          sqr(x1 - R(9) - R(5) * cos(q2)) + sqr(x2 - R(5) * sin(q2)) - R(64)};
    };
    r.solution = [](std::mt19937& g) {
      for (;;) {
        R q1(uniform(g, -3.14159, 3.14159)), q2(uniform(g, -3.14159, 3.14159));
        // x is on the circle (C1, 5) and on the circle (C2, 8).
        R c1x = R(8) * cos(q1), c1y = R(8) * sin(q1);
        R c2x = R(9) + R(5) * cos(q2), c2y = R(5) * sin(q2);
        R dx = c2x - c1x, dy = c2y - c1y;
        R d = sqrt(sqr(dx) + sqr(dy));
        if (!(d > R(3.001) && d < R(12.999))) continue;
        R a = (R(25) - R(64) + sqr(d)) / (R(2) * d);
        R h = sqrt(R(25) - sqr(a));
        R sgn(std::bernoulli_distribution(0.5)(g) ? 1 : -1);
        R x1 = c1x + a * dx / d - sgn * h * dy / d;
        R x2 = c1y + a * dy / d + sgn * h * dx / d;
        return Point{x1, x2, q1, q2};
      }
    };
    v.push_back(r);
  }

  // ------------------------------------------------------------------ 3-RPR
  {
    RobotRef r;
    r.file = "3rpr.robot";
    r.name = "3-RPR";
    r.vars = {"x1", "x2", "x3", "q1", "q2", "q3"};
    r.n = 3;
    r.f = [](const Point& p) {
      const R &x1 = p[0], &x2 = p[1], &x3 = p[2], &q1 = p[3], &q2 = p[4], &q3 = p[5];
      R c = R("0.8822"), l2 = R("20.8"), b = R("15.9");
      return std::vector<R>{
          sqr(x1) + sqr(x2) - sqr(q1),
          sqr(x1 + R(17) * cos(x3) - b) + sqr(x2 + R(17) * sin(x3)) - sqr(q2),
          sqr(x1 + l2 * cos(x3 + c)) + sqr(x2 + l2 * sin(x3 + c) - R(10)) - sqr(q3)};
    };
    r.solution = [](std::mt19937& g) {
      R c = R("0.8822"), l2 = R("20.8"), b = R("15.9");
      for (;;) {
        R x1(uniform(g, -32, 32)), x2(uniform(g, -32, 32)), x3(uniform(g, -3.14159, 3.14159));
        R q1 = sqrt(sqr(x1) + sqr(x2));
        R q2 = sqrt(sqr(x1 + R(17) * cos(x3) - b) + sqr(x2 + R(17) * sin(x3)));
        R q3 = sqrt(sqr(x1 + l2 * cos(x3 + c)) + sqr(x2 + l2 * sin(x3 + c) - R(10)));
        auto in = [](const R& q) { return q >= R(10) && q <= R(32); };
        if (in(q1) && in(q2) && in(q3)) return Point{x1, x2, x3, q1, q2, q3};
      }
    };
    v.push_back(r);
  }

  // ------------------------------------------------------------------ 3-RRR*
  {
    RobotRef r;
    r.file = "3rrr_star.robot";
    r.name = "3-RRR*";
    r.vars = {"x1", "x2", "x3", "q1", "q2", "q3"};
    r.n = 3;
    // Equation i is |A_i(x) - 10 (cos q_i, sin q_i)|^2 = 100.
    auto anchors = [](const R& x1, const R& x2, const R& x3) {
      R s2 = sqrt(R(2)), pi4 = R::pi() / R(4);
      return std::vector<R>{x1 - R(10),
                            x2 - R(10),
                            x1 + R(10) * cos(x3) - R(10),
                            x2 + R(10) * sin(x3) - R(10),
                            x1 + R(10) * s2 * cos(x3 + pi4),
                            x2 + R(10) * s2 * sin(x3 + pi4) - R(10)};
    };
    r.f = [anchors](const Point& p) {
      std::vector<R> a = anchors(p[0], p[1], p[2]);
      std::vector<R> out;
      for (int i = 0; i < 3; ++i)
        out.push_back(sqr(a[2 * i] - R(10) * cos(p[3 + i])) +
                      sqr(a[2 * i + 1] - R(10) * sin(p[3 + i])) - R(100));
      return out;
    };
    r.solution = [anchors](std::mt19937& g) {
      for (;;) {
        R x1(uniform(g, -12, 32)), x2(uniform(g, -12, 32)), x3(0.0);  // x3 is fixed at 0
        std::vector<R> a = anchors(x1, x2, x3);
        Point p{x1, x2, x3, R(), R(), R()};
        bool ok = true;
        for (int i = 0; i < 3 && ok; ++i)
          ok = circle_angle(a[2 * i], a[2 * i + 1], 10, std::bernoulli_distribution(0.5)(g),
                            p[3 + i]);
        if (ok) return p;
      }
    };
    v.push_back(r);
  }
  return v;
}

}  // namespace aspects_test
