#include "model/point_eval.h"

#include <cmath>

namespace aspects {

PointEvaluator::PointEvaluator(const Dag& dag) : dag_(dag), v_(dag.size(), 0.0) {}

bool PointEvaluator::run(const std::vector<int>& program, const double* vars) {
  if (int(v_.size()) < dag_.size()) v_.resize(dag_.size(), 0.0);
  for (int id : program) {
    const Node& n = dag_.node(id);
    const double a = n.a >= 0 ? v_[n.a] : 0, b = n.b >= 0 ? v_[n.b] : 0;
    double r = 0;
    switch (n.op) {
      case Op::Const: r = dag_.constant_value(id).mid(); break;
      case Op::Var: r = vars[n.k]; break;
      case Op::Add: r = a + b; break;
      case Op::Sub: r = a - b; break;
      case Op::Mul: r = a * b; break;
      case Op::Div: r = a / b; break;
      case Op::Min: r = std::min(a, b); break;
      case Op::Max: r = std::max(a, b); break;
      case Op::Neg: r = -a; break;
      case Op::Sqr: r = a * a; break;
      case Op::Sqrt: r = std::sqrt(a); break;
      case Op::Sin: r = std::sin(a); break;
      case Op::Cos: r = std::cos(a); break;
      case Op::Tan: r = std::tan(a); break;
      case Op::Exp: r = std::exp(a); break;
      case Op::Log: r = std::log(a); break;
      case Op::Abs: r = std::fabs(a); break;
      case Op::Asin: r = std::asin(a); break;
      case Op::Acos: r = std::acos(a); break;
      case Op::Atan: r = std::atan(a); break;
      case Op::Pow: r = std::pow(a, n.k); break;
      case Op::Sign: r = a > 0 ? 1 : a < 0 ? -1 : 0; break;
      case Op::Step: r = a < b ? 1 : 0; break;
    }
    if (!std::isfinite(r)) return false;
    v_[id] = r;
  }
  return true;
}

}  // namespace aspects
