#include "model_eval.h"

namespace aspects {

ModelEvaluator::ModelEvaluator(const Model& m)
    : m_(m), ev_(m.dag), zero_(0.0) {
  prog_f_ = m.dag.closure(m.equations);
  prog_fq_ = m.dag.closure(m.fq);
  prog_fx_ = m.dag.closure(m.fx);
  for (int e : m.equations) prog_eq_.push_back(m.dag.closure({e}));
}

EvalStatus ModelEvaluator::equations(const Box& box, std::vector<Interval>& f) {
  EvalStatus s = ev_.forward(prog_f_, box);
  f.resize(m_.equations.size());
  for (size_t i = 0; i < m_.equations.size(); ++i) f[i] = ev_.value(m_.equations[i]);
  return s;
}

static EvalStatus eval_matrix(Evaluator& ev, const std::vector<int>& prog,
                              const std::vector<int>& nodes, int n, const Box& box, IMatrix& J) {
  EvalStatus s = ev.forward(prog, box);
  if (J.rows() != n || J.cols() != n) J = IMatrix(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) J(i, j) = ev.value(nodes[i * n + j]);
  return s;
}

EvalStatus ModelEvaluator::jacobian_q(const Box& box, IMatrix& J) {
  return eval_matrix(ev_, prog_fq_, m_.fq, n(), box, J);
}

EvalStatus ModelEvaluator::jacobian_x(const Box& box, IMatrix& J) {
  return eval_matrix(ev_, prog_fx_, m_.fx, n(), box, J);
}

bool ModelEvaluator::hc4(int i, Box& box) {
  return ev_.hc4_revise(prog_eq_[i], m_.equations[i], zero_, box);
}

}  // namespace aspects
