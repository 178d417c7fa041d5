// The DAG at a point, in doubles rounded to nearest: for choices only (Newton's guesses of a
// solution, a star centre's search), never for a claim. A claim is proved on intervals
// afterwards (core/model/eval.h).
#pragma once

#include <vector>

#include "model/expr.h"

namespace aspects {

class PointEvaluator {
 public:
  explicit PointEvaluator(const Dag& dag);
  // Evaluates the nodes of `program` (a Dag::closure, increasing ids) at `vars` (model
  // order); false when a node is undefined or not finite there.
  bool run(const std::vector<int>& program, const double* vars);
  double value(int id) const { return v_[id]; }

 private:
  const Dag& dag_;
  std::vector<double> v_;
};

}  // namespace aspects
