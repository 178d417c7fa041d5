// Prune of Algorithm 1 (paper 4.2.2) for f(x, q) = 0: a fixpoint of HC4-Revise over the
// equations, then one Hansen–Sengupta contraction of the commands (intersected with the
// box). It removes no solution of f = 0 from the box; the result is rounded outward to
// doubles. When it proves that the box holds no solution it says which test did.
#pragma once

#include <vector>

#include "hansen_sengupta.h"
#include "model/model_eval.h"
#include "search/contractor.h"

namespace aspects {

class EquationContractor : public Contractor {
 public:
  explicit EquationContractor(ModelEvaluator& ev) : ev_(ev) {}
  Refutation contract(Box& box) override;

 private:
  ModelEvaluator& ev_;
  HsWorkspace ws_;
  std::vector<Interval> image_;
};

}  // namespace aspects
