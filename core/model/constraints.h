// Additional constraints (paper 5.4): three-valued truth of the model's constraint
// formulas on a box, from interval enclosures of their atoms g >= 0 (or g > 0).
//   True:    the formula holds at every point of the box (the inner test of Prove);
//   False:   it holds at no point of the box (Prune may discard the box);
//   Unknown: neither could be shown.
// A point where an atom's expression is undefined does not satisfy the atom.
#pragma once

#include "model/model_eval.h"

namespace aspects {

enum class Truth : uint8_t { False, True, Unknown };

class ConstraintChecker {
 public:
  ConstraintChecker(const Model& m, ModelEvaluator& ev);
  bool empty() const { return m_.constraints.empty(); }
  // Conjunction of every constraint on the box. When False, *violated (if given) is
  // the index of a constraint that is false on the whole box.
  Truth evaluate(const Box& box, int* violated = nullptr);

 private:
  Truth truth(int formula_node, EvalStatus status) const;

  const Model& m_;
  ModelEvaluator& ev_;
  std::vector<int> program_;
};

}  // namespace aspects
