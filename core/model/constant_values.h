// Enclosures of the constant nodes of a DAG that is still growing (the parser's domain
// bounds), each node evaluated once whatever the DAG's size.
//
// An evaluator over the whole DAG costs several intervals per node to create: one per
// domain bound made parsing quadratic in the model's size. This one copies into a DAG of
// its own only the nodes the bounds use, and keeps their values from one bound to the next.
#pragma once

#include <unordered_map>

#include "model/expr.h"
#include "model/interval_eval.h"
#include "numerics/interval.h"

namespace aspects {

class ConstantValues {
 public:
  explicit ConstantValues(const Dag& dag) : dag_(dag), eval_(copies_) {}
  ConstantValues(const ConstantValues&) = delete;
  ConstantValues& operator=(const ConstantValues&) = delete;

  // The enclosure of `node`, which must not depend on a variable: the same interval the
  // engine's evaluator gives it (empty where it is undefined).
  const Interval& value(int node);

 private:
  int copy(int node);  // its id in copies_, copying the nodes below it first (no recursion)

  const Dag& dag_;
  Dag copies_;
  std::unordered_map<int, int> copy_of_;  // dag_ id -> copies_ id
  IntervalEvaluator<Interval> eval_;      // on copies_
  int evaluated_ = 0;                     // copies_ ids below it have their values
};

}  // namespace aspects
