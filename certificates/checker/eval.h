// eval.h — interval evaluation of the model's expression DAG in MPFI: natural forward
// evaluation, the three-valued truth of the constraints (FORMAT.md, "Constraints"),
// forward-mode interval AD for the Jacobians, and HC4-Revise.
#pragma once

#include <vector>

#include "ival.h"
#include "model.h"

namespace cc {

enum class Mode { Proof, Refute, Truth };

// Thrown when a check needs more work than the checker allows (Evaluator::work_limit).
struct WorkLimit : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Evaluator {
 public:
  explicit Evaluator(const Model& m);
  const Model& model() const { return m_; }
  int nv() const { return int(m_.vars.size()); }

  // Values of the nodes of `prog` on `box` (one interval per variable). Proof: true iff
  // every node is defined and finite on the whole box. Refute: false only when some node
  // is defined nowhere on the box (then no point of the box is a solution). Truth: never.
  bool eval(const std::vector<int>& prog, const Ival* box, Mode mode);
  // Kleene truth of the conjunction of every constraint on box: 0 False, 1 Unknown, 2 True.
  int feasible(const Ival* box);
  // Proof-mode values and derivatives w.r.t. the variables whose bit is set in `dirs`.
  bool eval_ad(const std::vector<int>& prog, const Ival* box, uint64_t dirs);
  const Ival& val(int id) const { return val_[id]; }
  const Ival& der(int id, int var) const { return der_[size_t(id) * nv() + var]; }
  // HC4-Revise of equation `eq` (= 0) on box; false: the box holds no solution of it.
  bool hc4(int eq, Ival* box);
  // The value of a constant node (domain bounds); false if undefined or unbounded.
  bool constant(int id, Ival& out) const;

  std::vector<int> closure(const std::vector<int>& roots) const;
  std::vector<int> all_eqs, all_atoms;           // program of every equation, of every atom
  std::vector<std::vector<int>> eq_prog, factor_prog;
  Ival two_pi;
  // Node evaluations (forward, derivative, backward) so far; past `work_limit` (set by
  // main.cpp from the bytes read), eval(), eval_ad() and hc4() throw WorkLimit.
  uint64_t work = 0;
  uint64_t work_limit = UINT64_MAX;

 private:
  void charge(size_t nodes) {
    work += nodes;
    if (work > work_limit)
      throw WorkLimit("the check needs more work than the checker allows for its size");
  }
  int apply(int id, Ival& r, const Ival* a, const Ival* b);
  int truth(int formula) const;
  void trig(bool cosine, int child, const Ival& a, Ival& r);
  void power(Ival& r, const Ival& a, int k);
  bool derive(int id);
  bool backward(int id, Ival* box);
  bool monotone_projection(Op op, const Ival& r, Ival& a, const Ival& fa);
  bool project_general(Op op, const Ival& r, Ival& a);
  void branch_inverse(Op op, mpfr_srcptr y, int s, double c, Ival& out);
  bool hull_both(Ival& a, const Ival& s);  // a ∩= (s ∪ −s)
  bool meet_nonnegative(Ival& r);
  bool project_square(Ival& r, Ival& a);

  const Model& m_;
  std::vector<Ival> val_, der_, cval_;
  // Per node: 0 defined (and finite) on the whole box, 1 partial or unbounded, 2 nowhere.
  std::vector<int> cstat_, st_;  // constant nodes (once), every node (last evaluation)
  // One-entry cache of sin and cos per argument node: MPFR trigonometry is the costly
  // part, and sin(q)/cos(q) pairs, sin/cos derivatives and neighbouring slabs hit it.
  struct TrigCache {
    Ival arg, sin, cos;
  };
  std::vector<TrigCache> tc_;
  void sincos(const Ival& a, Ival& s, Ival& c);
  void extremum(Ival& v, const Ival& a, double off, double lo, double hi);
  Ival pi_;
  uint64_t dirs_ = 0;
  Ival t1_, t2_, t3_, t4_, g_;
};

}  // namespace cc
