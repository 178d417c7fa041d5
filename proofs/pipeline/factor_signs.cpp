#include "factor_signs.h"

#include "checker_margins.h"

namespace aspects {

namespace {

int sign_with_margin(const Interval& d) {
  double lo = d.lo_down(), hi = d.hi_up();
  double margin = margins::sign_clearance() * (hi - lo) + margins::sign_clearance_abs;
  if (lo > margin) return 1;
  if (hi < -margin) return -1;
  return 0;
}

}  // namespace

FactorSigns::FactorSigns(ModelEvaluator& ev, const Model& m, const std::vector<Factor>& factors)
    : ev_(ev) {
  for (const auto& f : factors) nodes_.push_back(f.node);
  program_ = m.dag.closure(nodes_);
}

void FactorSigns::of(const Box& box, int8_t* signs) {
  stored_.resize(box.size());
  for (size_t v = 0; v < box.size(); ++v) stored_[v].set_hull(box[v].lo_down(), box[v].hi_up());
  const bool defined = ev_.nodes(program_, stored_) == EvalStatus::Defined;
  for (size_t i = 0; i < nodes_.size(); ++i)
    signs[i] = defined ? int8_t(sign_with_margin(ev_.value(nodes_[i]))) : 0;
}

}  // namespace aspects
