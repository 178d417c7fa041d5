// Prove of Algorithm 1 (paper 4.2.1): is a cell of the search a solution box?
//
// prove() returns Verdict::Solution only when all of these hold for the reported box
// B = ([x], [q]) it writes, [x] the cell's pose:
//  - P1: for every x in [x] there is exactly one q in [q~] with f(x, q) = 0, and it lies
//    in [q] ⊆ [q~] (parametric Hansen–Sengupta, iteration (9));
//  - coverage: the cell's commands lie in [q~], so every solution of the cell is in B
//    (no branch of the cell is lost: the separation bound relies on it);
//  - domain: [q] lies in the declared domain of every non-periodic command (its inner
//    enclosure), and the pose meets the declared domain;
//  - P2: Fx and Fq are strongly regular on B;
//  - inner test: every additional constraint is certainly true on B.
// Otherwise it returns the first property that failed, in that order (a failed P1 as
// Verdict::WidePose when the pose's spread blocked it, else Verdict::NoExistence). The recorded
// numbers (the proof) are widened by the margins of checker_margins.h.
#pragma once

#include <vector>

#include "model/constraints.h"
#include "hansen_sengupta.h"
#include "model/model_eval.h"
#include "search/verdict.h"

namespace aspects {

// What a solution box's proofs used (recorded in the certificate).
struct SolutionProof {
  ExistenceProof existence;    // iteration (9) from the cell
  std::vector<double> cx, cq;  // preconditioners of the P2 tests of Fx and Fq
  std::vector<double> dx, dq;  // their column weights (1 unless the unscaled test failed)
};

// Prove's part of Algorithm 1, as the search receives it.
class BoxProver {
 public:
  virtual ~BoxProver() = default;
  // On Verdict::Solution, `reported` is B and `proof` its certificate data.
  virtual Verdict prove(const Box& cell, Box& reported, SolutionProof& proof) = 0;
};

class SolutionBoxProver : public BoxProver {
 public:
  // grid: Q~ and IMAGE on the grids format 3 codes them against (proofs/certificate_grid.h).
  SolutionBoxProver(ModelEvaluator& ev, ConstraintChecker& constraints, double tau,
                    int max_iterations, bool grid = false);
  Verdict prove(const Box& cell, Box& reported, SolutionProof& proof) override;

 private:
  bool covers_cell(const ExistenceProof& ex, const Box& cell) const;
  void on_grid(double& lo, double& hi, const Interval& q, const Variable& var) const;

  ModelEvaluator& ev_;
  ConstraintChecker& constraints_;
  const Model& m_;
  double tau_;
  int max_iterations_;
  bool grid_;
  Box retry_;
  HsWorkspace ws_;
  IMatrix J_;
};

}  // namespace aspects
