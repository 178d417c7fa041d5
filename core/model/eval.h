// Interval evaluation of the expression DAG (forward) and HC4-Revise (backward
// projection), as the rest of the engine calls them. Forward: value(id) encloses the
// node's range over the points of the box where the node is defined. Backward:
// hc4_revise never removes a point of the box at which the constraint holds (and is
// defined).
//
// Both run on the evaluator of core/model/interval_eval.h: on doubles first at a working
// precision of 53 bits (unless made with Arithmetic::MpfiOnly), where the ends
// are MPFI's and MPFR's arithmetic is avoided; on MPFI whenever doubles decline, from the
// start of the program, and at every other precision.
#pragma once

#include <memory>
#include <vector>

#include "model/eval_status.h"
#include "model/expr.h"
#include "model/interval_eval.h"
#include "numerics/arithmetic.h"
#include "numerics/double_interval.h"
#include "numerics/interval.h"

namespace aspects {

class Evaluator {
 public:
  // The precision is this thread's working precision when it is made.
  explicit Evaluator(const Dag& dag, Arithmetic arithmetic = Arithmetic::DoublesFirst);

  // How it computes: DoublesFirst only when asked to and made at 53 bits.
  Arithmetic arithmetic() const {
    return doubles_ ? Arithmetic::DoublesFirst : Arithmetic::MpfiOnly;
  }

  // Evaluates the nodes of `program` (a Dag::closure, increasing ids) on the box.
  EvalStatus forward(const std::vector<int>& program, const Box& box);
  const Interval& value(int id) const;
  // The same with double ends (rounded outward; exact at 53 bits).
  DInterval value_d(int id) const;

  // Contracts `box` with respect to node(root) ∈ target. Returns false when the box
  // holds no point satisfying the constraint (the box is then unchanged).
  bool hc4_revise(const std::vector<int>& program, int root, const Interval& target, Box& box);

 private:
  void fit_values() const;

  std::unique_ptr<IntervalEvaluator<DInterval>> doubles_;  // null unless at 53 bits
  IntervalEvaluator<Interval> mpfi_;
  const Dag& dag_;
  bool from_doubles_ = false;  // the last pass ran in doubles_
  mutable std::vector<Interval> from_doubles_values_;  // value() after a pass in doubles_
};

}  // namespace aspects
