// The model's constraints reduced on a box B (certificates/FORMAT.md, "Counting", C7): with
// Kleene's three-valued truth of each atom on B (model/constraints.h), an atom True on B
// holds at every point of B and an atom False on B at none, so at every point of B each
// formula has the value of the formula left after dropping True conjuncts and False
// disjuncts, an `and` with a False conjunct being False and an `or` with a True disjunct
// True. When what is left of every constraint is a conjunction of Unknown atoms, the
// feasible points of B are exactly the points of B where each of those atoms holds: each
// one becomes a constraint of the pieces (strict g > 0 or closed g ≥ 0). An `or` with two
// Unknown disjuncts or more leaves a union: what is left, expanded into a disjunction of at
// most kMaxTerms conjunctions of atoms (`terms`), makes the piece a union of sets each given
// by conjunctions, which is star-shaped about v when each of them is (C7).
#pragma once

#include <cstdint>
#include <vector>

#include "model/model_eval.h"

namespace aspects {

enum class Reduced : uint8_t {
  True,         // every constraint holds on the whole box
  False,        // some constraint holds nowhere on the box
  Atoms,        // the feasible points are those where every atom of `atoms` holds
  Disjunction,  // an `or` of two Unknown disjuncts or more remains: a union of `terms`
};

struct ReducedConstraints {
  Reduced outcome = Reduced::True;
  std::vector<int> atoms;  // indices into model.constraint_atoms (Atoms only)
  // Disjunction: the feasible points of the box are those where every atom of some term
  // holds (each term: indices into model.constraint_atoms); empty when longer than kMaxTerms.
  std::vector<std::vector<int>> terms;
};

constexpr size_t kMaxTerms = 4;

class ConstraintReducer {
 public:
  explicit ConstraintReducer(const Model& m);
  bool empty() const { return m_.constraints.empty(); }
  ReducedConstraints reduce(ModelEvaluator& ev, const Box& box) const;
  // Atom k (an index into model.constraint_atoms): strict (g > 0) or closed (g ≥ 0).
  bool strict(int k) const { return strict_[k]; }

 private:
  struct Part {
    int truth;  // 0 False, 1 Unknown, 2 True
    std::vector<std::vector<int>> dnf = {};  // Unknown: what is left, or- of and- of atoms
    bool overflow = false;                   // Unknown: more than kMaxTerms terms
  };
  Part reduce(ModelEvaluator& ev, int formula, bool defined) const;

  const Model& m_;
  std::vector<int> program_;
  std::vector<int> atom_of_formula_;  // formula node -> index in constraint_atoms (-1)
  std::vector<bool> strict_;
};

}  // namespace aspects
