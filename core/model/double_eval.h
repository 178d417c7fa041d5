// The evaluator's fast path at 53 bits: the forward evaluation and HC4-Revise of
// core/model/eval.cpp with double endpoints (core/numerics/double_interval.h), giving the same ends bit
// for bit as the MPFI evaluator for every operation it takes. MPFR's arithmetic was most
// of the run time (bench/RESULTS.md, "Interval arithmetic on doubles").
//
// It takes const, var, + − × /, min, max, neg, sqr, positive powers, sqrt, sin, cos, abs,
// sign and step. Anything else — another operation, a divisor or a negative power's base
// that may vanish, a sqrt argument that may be negative, a value that is not finite — it
// hands back undecided (nullopt), and the caller runs the MPFI evaluator from the start:
// no answer comes from a shortcut.
#pragma once

#include <optional>
#include <vector>

#include "numerics/double_interval.h"
#include "model/eval_status.h"
#include "model/expr.h"
#include "numerics/interval.h"
#include "numerics/sincos.h"

namespace aspects {

class DoubleEvaluator {
 public:
  // Only meaningful at a working precision of 53 bits (every endpoint a double).
  explicit DoubleEvaluator(const Dag& dag);

  // As Evaluator::forward; nullopt when the MPFI evaluator must decide.
  std::optional<EvalStatus> forward(const std::vector<int>& program, const Box& box);
  DInterval value(int id) const { return v_[id]; }

  // As Evaluator::hc4_revise with node(root) ∈ target; nullopt, with the box untouched,
  // when the MPFI evaluator must decide.
  std::optional<bool> hc4_revise(const std::vector<int>& program, int root, DInterval target,
                                 Box& box);

 private:
  enum class Step { Narrowed, Empty, Unsupported };  // outcome of one backward projection
  Step backward(int id);
  Step project_periodic(bool is_sin, DInterval& r, DInterval& a);
  void sin_cos_of(int arg_id, const DInterval& arg);
  DInterval power(const DInterval& a, int k);

  const Dag& dag_;
  std::vector<DInterval> v_, fwd_;
  std::vector<DInterval> consts_;  // per node id; Const nodes only
  std::vector<DInterval> box_;     // the variables as read by forward, narrowed by backward
  std::vector<DInterval> trig_arg_, trig_sin_, trig_cos_;  // last sin/cos per argument node
  std::vector<uint8_t> trig_ok_;
  SinCos sincos_;
  ArbBounds arb_;         // asin and acos for the periodic projections
  Interval mpfi_arg_, mpfi_sin_, mpfi_cos_;  // sin and cos across quadrants, by MPFI
  DInterval pi_, two_pi_;
};

}  // namespace aspects
