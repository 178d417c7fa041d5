#include "model/constraints.h"

namespace aspects {

ConstraintChecker::ConstraintChecker(const Model& m, ModelEvaluator& ev) : m_(m), ev_(ev) {
  program_ = m.dag.closure(m.constraint_atoms);
}

Truth ConstraintChecker::truth(int id, EvalStatus status) const {
  const FormulaNode& f = m_.formula[id];
  if (f.kind == FormulaNode::Atom) {
    const Interval& g = ev_.value(f.expr);
    if (g.empty()) return Truth::False;  // undefined on the whole box
    mpfr_srcptr lo = &g.get()->left, hi = &g.get()->right;
    bool holds = f.strict ? mpfr_sgn(lo) > 0 : mpfr_sgn(lo) >= 0;
    bool fails = f.strict ? mpfr_sgn(hi) <= 0 : mpfr_sgn(hi) < 0;
    if (fails) return Truth::False;
    // "Holds everywhere" needs g defined everywhere (Partial: undefined somewhere).
    if (holds && status == EvalStatus::Defined) return Truth::True;
    return Truth::Unknown;
  }
  bool is_and = f.kind == FormulaNode::And;
  Truth acc = is_and ? Truth::True : Truth::False;
  for (int k : f.kids) {
    Truth t = truth(k, status);
    if (is_and) {
      if (t == Truth::False) return Truth::False;
      if (t == Truth::Unknown) acc = Truth::Unknown;
    } else {
      if (t == Truth::True) return Truth::True;
      if (t == Truth::Unknown) acc = Truth::Unknown;
    }
  }
  return acc;
}

Truth ConstraintChecker::evaluate(const Box& box, int* violated) {
  if (m_.constraints.empty()) return Truth::True;
  // One status for the whole program is conservative: Partial anywhere blocks True.
  EvalStatus status = ev_.nodes(program_, box);
  Truth all = Truth::True;
  for (size_t c = 0; c < m_.constraints.size(); ++c) {
    Truth t = truth(m_.constraints[c].root, status);
    if (t == Truth::False) {
      if (violated) *violated = int(c);
      return Truth::False;
    }
    if (t == Truth::Unknown) all = Truth::Unknown;
  }
  return all;
}

}  // namespace aspects
