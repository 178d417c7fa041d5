// Interval evaluation of a model's equations and Jacobians on a box, with
// preallocated workspaces (no allocation per call). One ModelEvaluator per thread.
#pragma once

#include <vector>

#include "model/eval.h"
#include "model/model.h"
#include "model/point_eval.h"

namespace aspects {

class ModelEvaluator {
 public:
  explicit ModelEvaluator(const Model& m, Arithmetic arithmetic = Arithmetic::DoublesFirst);

  // How it computes (eval.h): the proofs' sweeps on it follow it (proofs/hansen_sengupta.h).
  Arithmetic arithmetic() const { return ev_.arithmetic(); }

  const Model& model() const { return m_; }
  int n() const { return m_.n(); }

  // f_i over the box (model-order variables).
  EvalStatus equations(const Box& box, std::vector<Interval>& f);
  // Fq (or Fx) over the box, n×n.
  EvalStatus jacobian_q(const Box& box, IMatrix& J);
  EvalStatus jacobian_x(const Box& box, IMatrix& J);
  // The same with double ends, for a working precision of 53 bits (exact there).
  EvalStatus equations(const Box& box, std::vector<DInterval>& f);
  EvalStatus jacobian_q(const Box& box, DMatrix& J);
  EvalStatus jacobian_x(const Box& box, DMatrix& J);
  // Any set of nodes (e.g. separation factors): values readable through value().
  EvalStatus nodes(const std::vector<int>& program, const Box& box) {
    return ev_.forward(program, box);
  }
  const Interval& value(int node) const { return ev_.value(node); }

  // f, Fx and Fq (row major) at a point, in doubles rounded to nearest: for choices only
  // (model/point_eval.h). False where a node is undefined or not finite.
  bool at_point(const double* vars, std::vector<double>& f, std::vector<double>& fx,
                std::vector<double>& fq);

  // HC4-Revise on equation i; false when the box holds no solution of it.
  bool hc4(int i, Box& box);

 private:
  const Model& m_;
  Evaluator ev_;
  std::vector<int> prog_f_, prog_fq_, prog_fx_, prog_point_;
  PointEvaluator point_;
  std::vector<std::vector<int>> prog_eq_;
  Interval zero_;
};

}  // namespace aspects
