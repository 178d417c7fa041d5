#include "counting/constraint_reduction.h"

#include <algorithm>

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

namespace {

// The conjunction of two DNFs: every pair of terms, each term's atoms sorted and unique.
std::vector<std::vector<int>> product(const std::vector<std::vector<int>>& a,
                                      const std::vector<std::vector<int>>& b) {
  std::vector<std::vector<int>> out;
  for (const auto& x : a)
    for (const auto& y : b) {
      std::vector<int> t = x;
      t.insert(t.end(), y.begin(), y.end());
      std::sort(t.begin(), t.end());
      t.erase(std::unique(t.begin(), t.end()), t.end());
      out.push_back(std::move(t));
    }
  return out;
}

}  // namespace

// The atoms' truth is model/constraints.h's (one status for every atom: undefined
// somewhere blocks True). What is left of an Unknown formula, as a disjunction of
// conjunctions of its Unknown atoms (too long: `overflow`).
ConstraintReducer::Part ConstraintReducer::reduce(ModelEvaluator& ev, int id, bool defined) const {
  const FormulaNode& f = m_.formula[id];
  if (f.kind == FormulaNode::Atom) {
    const Interval& g = ev.value(f.expr);
    if (g.empty()) return {0};  // undefined on the whole box
    mpfr_srcptr lo = &g.get()->left, hi = &g.get()->right;
    if (f.strict ? mpfr_sgn(hi) <= 0 : mpfr_sgn(hi) < 0) return {0};
    if (defined && (f.strict ? mpfr_sgn(lo) > 0 : mpfr_sgn(lo) >= 0)) return {2};
    return {1, {{atom_of_formula_[id]}}};
  }
  const bool is_and = f.kind == FormulaNode::And;
  Part out{1, {}};
  if (is_and) out.dnf = {{}};
  int unknown = 0;
  for (int k : f.kids) {
    Part p = reduce(ev, k, defined);
    if (p.truth == (is_and ? 0 : 2)) return {p.truth};  // decides the whole formula
    if (p.truth != 1) continue;
    ++unknown;
    out.overflow = out.overflow || p.overflow;
    if (out.overflow) continue;
    if (is_and) {
      out.dnf = product(out.dnf, p.dnf);
    } else {
      out.dnf.insert(out.dnf.end(), p.dnf.begin(), p.dnf.end());
    }
    out.overflow = out.dnf.size() > kMaxTerms;
  }
  if (unknown == 0) return {is_and ? 2 : 0};
  if (out.overflow) out.dnf.clear();
  return out;
}

ReducedConstraints ConstraintReducer::reduce(ModelEvaluator& ev, const Box& box) const {
  ReducedConstraints out;
  if (m_.constraints.empty()) return out;
  const bool defined = ev.nodes(program_, box) == EvalStatus::Defined;
  std::vector<std::vector<int>> dnf{{}};
  bool unknown = false, overflow = false;
  for (const Constraint& c : m_.constraints) {
    Part p = reduce(ev, c.root, defined);
    if (p.truth == 0) {
      out.outcome = Reduced::False;
      return out;
    }
    if (p.truth != 1) continue;
    unknown = true;
    overflow = overflow || p.overflow;
    if (!overflow) dnf = product(dnf, p.dnf);
    overflow = overflow || dnf.size() > kMaxTerms;
  }
  if (!unknown) return out;  // True
  if (!overflow && dnf.size() == 1) {
    out.outcome = Reduced::Atoms;
    out.atoms = std::move(dnf[0]);
    return out;
  }
  out.outcome = Reduced::Disjunction;
  if (!overflow) out.terms = std::move(dnf);
  return out;
}

}  // namespace aspects
