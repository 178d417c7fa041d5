#include "counting/constraint_reduction.h"

namespace aspects {

ConstraintReducer::ConstraintReducer(const Model& m) : m_(m) {
  program_ = m.dag.closure(m.constraint_atoms);
  // The parser appends an atom's node to constraint_atoms as it appends its formula node.
  atom_of_formula_.assign(m.formula.size(), -1);
  int k = 0;
  for (size_t f = 0; f < m.formula.size(); ++f)
    if (m.formula[f].kind == FormulaNode::Atom) {
      atom_of_formula_[f] = k++;
      strict_.push_back(m.formula[f].strict);
    }
}

// The atoms' truth is model/constraints.h's (one status for every atom: undefined
// somewhere blocks True).
ConstraintReducer::Part ConstraintReducer::reduce(ModelEvaluator& ev, int id, bool defined,
                                                  std::vector<int>& atoms) const {
  const FormulaNode& f = m_.formula[id];
  if (f.kind == FormulaNode::Atom) {
    const Interval& g = ev.value(f.expr);
    if (g.empty()) return {0};  // undefined on the whole box
    mpfr_srcptr lo = &g.get()->left, hi = &g.get()->right;
    if (f.strict ? mpfr_sgn(hi) <= 0 : mpfr_sgn(hi) < 0) return {0};
    if (defined && (f.strict ? mpfr_sgn(lo) > 0 : mpfr_sgn(lo) >= 0)) return {2};
    atoms.push_back(atom_of_formula_[id]);
    return {1, true};
  }
  const bool is_and = f.kind == FormulaNode::And;
  const size_t mark = atoms.size();
  int unknown = 0;
  bool conjunction = true;
  for (int k : f.kids) {
    const size_t before = atoms.size();
    const Part p = reduce(ev, k, defined, atoms);
    if (p.truth == (is_and ? 0 : 2)) {  // decides the whole formula
      atoms.resize(mark);
      return {p.truth};
    }
    if (p.truth != 1) {
      atoms.resize(before);
      continue;
    }
    ++unknown;
    conjunction = conjunction && p.conjunction;
  }
  if (unknown == 0) {
    atoms.resize(mark);
    return {is_and ? 2 : 0};
  }
  // An `or` whose one Unknown disjunct is left is that disjunct.
  if (!is_and && unknown > 1) conjunction = false;
  return {1, conjunction};
}

ReducedConstraints ConstraintReducer::reduce(ModelEvaluator& ev, const Box& box) const {
  ReducedConstraints out;
  if (m_.constraints.empty()) return out;
  const bool defined = ev.nodes(program_, box) == EvalStatus::Defined;
  bool conjunction = true, unknown = false;
  for (const Constraint& c : m_.constraints) {
    const Part p = reduce(ev, c.root, defined, out.atoms);
    if (p.truth == 0) {
      out.outcome = Reduced::False;
      out.atoms.clear();
      return out;
    }
    if (p.truth == 1) unknown = true, conjunction = conjunction && p.conjunction;
  }
  if (!unknown) {
    out.outcome = Reduced::True;
    out.atoms.clear();
  } else if (!conjunction) {
    out.outcome = Reduced::Disjunction;
    out.atoms.clear();
  } else {
    out.outcome = Reduced::Atoms;
  }
  return out;
}

}  // namespace aspects
