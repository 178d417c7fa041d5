#include "model/eval.h"

namespace aspects {

Evaluator::Evaluator(const Dag& dag, Arithmetic arithmetic)
    : doubles_(arithmetic == Arithmetic::DoublesFirst && working_precision() == 53
                   ? new IntervalEvaluator<DInterval>(dag)
                   : nullptr),
      mpfi_(dag),
      dag_(dag) {}

// Made at the first value() after a pass in doubles (many evaluators never need them),
// then fitted at each pass to nodes made since: never during a pass, which would move the
// values already handed out.
void Evaluator::fit_values() const {
  if (from_doubles_values_.size() < size_t(dag_.size()))
    from_doubles_values_.resize(size_t(dag_.size()));
}

const Interval& Evaluator::value(int id) const {
  if (!from_doubles_) return mpfi_.value(id);
  if (from_doubles_values_.empty()) fit_values();
  const DInterval d = doubles_->value(id);
  from_doubles_values_[id].set_hull(d.lo, d.hi);  // exact: both ends are doubles
  return from_doubles_values_[id];
}

DInterval Evaluator::value_d(int id) const {
  if (from_doubles_) return doubles_->value(id);
  return to_dinterval(mpfi_.value(id));
}

EvalStatus Evaluator::forward(const std::vector<int>& program, const Box& box) {
  if (doubles_) {
    if (std::optional<EvalStatus> s = doubles_->forward(program, box)) {
      from_doubles_ = true;
      if (!from_doubles_values_.empty()) fit_values();
      return *s;
    }
  }
  from_doubles_ = false;
  return *mpfi_.forward(program, box);  // MPFI never declines
}

bool Evaluator::hc4_revise(const std::vector<int>& program, int root, const Interval& target,
                           Box& box) {
  if (doubles_) {
    if (std::optional<bool> feasible =
            doubles_->hc4_revise(program, root, to_dinterval(target), box)) {
      from_doubles_ = true;
      if (!from_doubles_values_.empty()) fit_values();
      return *feasible;
    }
  }
  from_doubles_ = false;
  return *mpfi_.hc4_revise(program, root, target, box);
}

}  // namespace aspects
