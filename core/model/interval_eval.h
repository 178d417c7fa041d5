// The expression DAG evaluated on one interval type, written once: I = Interval (MPFI,
// any precision) or I = DInterval (double ends, only at a working precision of 53 bits,
// where every MPFI end is a double). Forward: value(id) encloses the node's range over
// the points of the box where the node is defined. HC4-Revise: never removes a point of
// the box at which the constraint holds (and is defined).
//
// The two instantiations give the same ends bit for bit: the algorithm is the same, and
// the primitives (core/numerics/evaluator_ops.h) round as MPFI does. Where doubles cannot,
// a primitive declines, and the evaluation answers nullopt with the box untouched: the
// caller reruns the program on MPFI from the start, so no answer comes from a shortcut.
// MPFI never declines.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "model/backward.h"
#include "model/eval_status.h"
#include "model/expr.h"
#include "numerics/double_interval.h"
#include "numerics/interval.h"
#include "numerics/sincos.h"

namespace aspects {

template <class I>
class IntervalEvaluator {
 public:
  explicit IntervalEvaluator(const Dag& dag);
  IntervalEvaluator(const IntervalEvaluator&) = delete;
  IntervalEvaluator& operator=(const IntervalEvaluator&) = delete;

  // Evaluates the nodes of `program` (a Dag::closure, increasing ids) on the box.
  std::optional<EvalStatus> forward(const std::vector<int>& program, const Box& box);
  const I& value(int id) const { return v_[id]; }

  // Contracts `box` with respect to node(root) ∈ target. false when the box holds no
  // point satisfying the constraint (the box is then unchanged).
  std::optional<bool> hc4_revise(const std::vector<int>& program, int root, const I& target,
                                 Box& box);

 private:
  // What one node's evaluation says, as EvalStatus, or that a primitive declined.
  enum class NodeEval { Defined, Partial, Undefined, Declined };

  // Inlined into forward's loop: a call per node is a measurable part of a pass.
  [[gnu::always_inline]] inline NodeEval forward_node(int id, const Box& box);
  NodeEval on_domain(Op op, I& r, const I& a);  // sqrt, log, asin, acos
  NodeEval sign_or_step(const Node& n, I& r, const I& a, const I* b);
  bool power(I& r, const I& a, int k);
  // sin and cos cost most of an evaluation; the models take both of the same argument,
  // and the same argument comes back often (HC4 rounds, Jacobians and factors on one
  // box). So both are computed together and kept, per argument node, with the last
  // argument they were computed for.
  const I& sin_cos_of(int arg_id, const I& arg, Op op);
  Projection backward(int id);
  void fit_to_dag();  // per-node arrays for nodes made after the evaluator

  const Dag& dag_;
  std::vector<I> v_;       // node values
  std::vector<I> fwd_;     // forward values, to see which nodes backward narrowed
  std::vector<I> consts_;  // the DAG's constants at this type's precision, by Node::k
  std::vector<I> trig_arg_, trig_sin_, trig_cos_;
  std::vector<uint8_t> trig_ok_;
  SinCos sincos_;
  I t1_, t2_, t3_, t4_;      // forward scratch
  BackwardScratch<I> bwd_;  // the backward kernels' scratch
};

extern template class IntervalEvaluator<Interval>;
extern template class IntervalEvaluator<DInterval>;

}  // namespace aspects
