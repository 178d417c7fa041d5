#include "model/model_eval.h"

namespace aspects {

ModelEvaluator::ModelEvaluator(const Model& m, Arithmetic arithmetic)
    : m_(m), ev_(m.dag, arithmetic), point_(m.dag), zero_(0.0) {
  prog_f_ = m.dag.closure(m.equations);
  std::vector<int> all = m.equations;
  all.insert(all.end(), m.fx.begin(), m.fx.end());
  all.insert(all.end(), m.fq.begin(), m.fq.end());
  prog_point_ = m.dag.closure(all);
  prog_fq_ = m.dag.closure(m.fq);
  prog_fx_ = m.dag.closure(m.fx);
  for (int e : m.equations) prog_eq_.push_back(m.dag.closure({e}));
}

namespace {

void read_value(const Evaluator& ev, int id, Interval& out) { out = ev.value(id); }
void read_value(const Evaluator& ev, int id, DInterval& out) { out = ev.value_d(id); }

template <class I>
EvalStatus eval_vector(Evaluator& ev, const std::vector<int>& prog, const std::vector<int>& nodes,
                       const Box& box, std::vector<I>& f) {
  EvalStatus s = ev.forward(prog, box);
  f.resize(nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) read_value(ev, nodes[i], f[i]);
  return s;
}

template <class I>
EvalStatus eval_matrix(Evaluator& ev, const std::vector<int>& prog, const std::vector<int>& nodes,
                       int n, const Box& box, Matrix<I>& J) {
  EvalStatus s = ev.forward(prog, box);
  if (J.rows() != n || J.cols() != n) J = Matrix<I>(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) read_value(ev, nodes[i * n + j], J(i, j));
  return s;
}

}  // namespace

EvalStatus ModelEvaluator::equations(const Box& box, std::vector<Interval>& f) {
  return eval_vector(ev_, prog_f_, m_.equations, box, f);
}
EvalStatus ModelEvaluator::equations(const Box& box, std::vector<DInterval>& f) {
  return eval_vector(ev_, prog_f_, m_.equations, box, f);
}
EvalStatus ModelEvaluator::jacobian_q(const Box& box, IMatrix& J) {
  return eval_matrix(ev_, prog_fq_, m_.fq, n(), box, J);
}
EvalStatus ModelEvaluator::jacobian_q(const Box& box, DMatrix& J) {
  return eval_matrix(ev_, prog_fq_, m_.fq, n(), box, J);
}
EvalStatus ModelEvaluator::jacobian_x(const Box& box, IMatrix& J) {
  return eval_matrix(ev_, prog_fx_, m_.fx, n(), box, J);
}
EvalStatus ModelEvaluator::jacobian_x(const Box& box, DMatrix& J) {
  return eval_matrix(ev_, prog_fx_, m_.fx, n(), box, J);
}

bool ModelEvaluator::at_point(const double* vars, std::vector<double>& f,
                              std::vector<double>& fx, std::vector<double>& fq) {
  if (!point_.run(prog_point_, vars)) return false;
  f.resize(m_.equations.size());
  for (size_t i = 0; i < f.size(); ++i) f[i] = point_.value(m_.equations[i]);
  fx.resize(m_.fx.size());
  for (size_t i = 0; i < fx.size(); ++i) fx[i] = point_.value(m_.fx[i]);
  fq.resize(m_.fq.size());
  for (size_t i = 0; i < fq.size(); ++i) fq[i] = point_.value(m_.fq[i]);
  return true;
}

bool ModelEvaluator::hc4(int i, Box& box) {
  return ev_.hc4_revise(prog_eq_[i], m_.equations[i], zero_, box);
}

}  // namespace aspects
