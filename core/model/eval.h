// Interval evaluation of the expression DAG (forward) and HC4-Revise (backward
// projection). Forward: value(id) encloses the node's range over the points of the box
// where the node is defined. Backward: hc4_revise never removes a point of the box at
// which the constraint holds (and is defined).
#pragma once

#include <memory>
#include <vector>

#include "model/backward.h"
#include "model/double_eval.h"
#include "model/eval_status.h"
#include "model/expr.h"
#include "numerics/interval.h"
#include "numerics/sincos.h"

namespace aspects {

class Evaluator {
 public:
  // With the double-endpoint fast path (core/model/double_eval.h) where it applies, when created
  // at a working precision of 53 bits and unless set_double_fast_path(false).
  explicit Evaluator(const Dag& dag);

  // Evaluates the nodes of `program` (a Dag::closure, increasing ids) on the box.
  EvalStatus forward(const std::vector<int>& program, const Box& box);
  const Interval& value(int id) const;
  // The same with double ends (rounded outward; exact at 53 bits).
  DInterval value_d(int id) const;

  // Contracts `box` with respect to node(root) ∈ target. Returns false when the box
  // holds no point satisfying the constraint (the box is then unspecified).
  bool hc4_revise(const std::vector<int>& program, int root, const Interval& target, Box& box);

 private:
  EvalStatus forward_mpfi(const std::vector<int>& program, const Box& box);
  bool backward(int id, Box& box);
  void eval_pow(Interval& out, const Interval& a, int k);

  // sin and cos cost most of an evaluation; the models take both of the same argument,
  // and the same argument comes back often (HC4 rounds, Jacobians and factors on one
  // box). So both are computed together and kept, per argument node, with the last
  // argument they were computed for.
  const Interval& sin_cos_of(int arg_id, const Interval& arg, Op op);

  const Dag& dag_;
  std::unique_ptr<DoubleEvaluator> doubles_;  // null unless at 53 bits
  bool from_doubles_ = false;                 // the last pass ran in doubles_
  mutable std::vector<Interval> v_;           // value() copies doubles_' values in
  std::vector<Interval> fwd_;  // forward values, to see which nodes backward narrowed
  std::vector<Interval> trig_arg_, trig_sin_, trig_cos_;
  std::vector<uint8_t> trig_ok_;
  SinCos sincos_;
  Interval t1_, t2_, t3_, t4_;  // forward scratch
  BackwardScratch bwd_;         // backward scratch (the kernels' temporaries)
  Interval two_pi_;
};

}  // namespace aspects
