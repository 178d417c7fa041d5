// proofs.h — the checker's proofs on one box: the parametric Hansen–Sengupta test of
// P1/P3 with a recorded preconditioner and inflated box, strong regularity of C·Fx and
// C·Fq (P2), enclosures of the sign factors, and the refutation procedure for contraction
// slabs and discarded cells (HC4 fixpoint, false constraints, Hansen–Sengupta contraction
// with the checker's own preconditioner, bisection). Boxes arrive as doubles, lo/hi pairs.
#pragma once

#include <string>
#include <vector>

#include "eval.h"

namespace cc {

struct Factor {
  enum Kind { DetFx, DetFq, DiagFx, DiagFq, User } kind;
  int arg = 0;  // 0-based entry or user factor
};

class Prover {
 public:
  explicit Prover(Evaluator& ev);
  void load(const double* lohi);  // box := the double box
  std::vector<Ival> box;          // nv intervals: the box the next call works on

  // P1/P3: y = q̌ − GS(C·Fq(x, Q), C·f(x, q̌)), x the pose part of `box`, Q the inflated box
  // (n lo/hi pairs), C row major. Returns nullptr on success, else why it failed. With
  // `pose` the roles swap (V records): x unknown in Q, Fx for Fq, the commands of `box` fixed.
  const char* newton(const double* Q, const double* C, bool pose = false);
  std::vector<Ival> y;
  // P2 on `box`: C_X·Fx·diag(D_X) and C_Q·Fq·diag(D_Q) strictly diagonally dominant
  // (D positive). Keeps the Jacobians.
  const char* regular(const double* CX, const double* CQ, const double* DX, const double* DQ);
  // Enclosure of a factor on `box`; false if not defined there. `jac` says whether the
  // Jacobians of `box` are already computed (by regular()).
  bool factor(const Factor& f, bool jac, Ival& out);
  // True when `box` provably holds no feasible solution of f = 0.
  bool refute();
  long refutations = 0, refute_boxes = 0;

 private:
  bool jacobians();
  bool dominant(const std::vector<Ival>& J, const double* C, const double* D);
  bool contract(std::vector<Ival>& b);
  int hs_contract(std::vector<Ival>& b);
  bool refute_rec(std::vector<Ival>& b, int depth, int& budget);
  void product(const std::vector<Ival>& J, const double* C, std::vector<Ival>& out);
  void rhs(const double* C);
  void gs_row(int i, const std::vector<Ival>& X, const std::vector<Ival>& c);
  void read_jacobians(bool pose);
  void dot(Ival& out, const double* C, const Ival* const* x);

  Evaluator& ev_;
  const Model& m_;
  int n_, nv_;
  uint64_t cmd_mask_ = 0, pose_mask_ = 0, all_mask_ = 0;
  std::vector<Ival> w_, Jx_, Jq_, A_, b_;
  Ival t1_, t2_;
};

}  // namespace cc
