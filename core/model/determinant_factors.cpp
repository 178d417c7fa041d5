#include "model/determinant_factors.h"

#include "model/model_info.h"

namespace aspects {

int symbolic_determinant(Dag& dag, const std::vector<int>& m, int n) {
  if (n == 1) return m[0];
  if (n == 2)
    return dag.binary(Op::Sub, dag.binary(Op::Mul, m[0], m[3]), dag.binary(Op::Mul, m[1], m[2]));
  int det = dag.zero();
  for (int j = 0; j < n; ++j) {
    if (m[j] == dag.zero()) continue;
    std::vector<int> minor;
    for (int i = 1; i < n; ++i)
      for (int k = 0; k < n; ++k)
        if (k != j) minor.push_back(m[i * n + k]);
    int term = dag.binary(Op::Mul, m[j], symbolic_determinant(dag, minor, n - 1));
    det = (j % 2 == 0) ? dag.binary(Op::Add, det, term) : dag.binary(Op::Sub, det, term);
  }
  return det;
}

namespace {
void add_matrix_factors(Model& model, const std::vector<int>& mat, const char* name,
                        std::vector<Factor>& out) {
  int n = model.n();
  auto names = model.var_names();
  MatrixShape shape = structural_shape(model.dag, mat, n);
  if (shape != MatrixShape::Full && n > 1) {
    for (int i = 0; i < n; ++i) {
      int d = mat[i * n + i];
      if (model.dag.is_constant(d)) continue;  // a nonzero constant carries no sign change
      out.push_back({d, model.dag.to_string(d, names),
                     std::string(shape_name(shape)) + " " + name + ", entry (" +
                         std::to_string(i + 1) + "," + std::to_string(i + 1) + ")",
                     std::string("diag") + name + " " + std::to_string(i + 1)});
    }
    return;
  }
  int det = symbolic_determinant(model.dag, mat, n);
  out.push_back({det, model.dag.to_string(det, names), std::string("det ") + name,
                 std::string("det") + name});
}
}  // namespace

std::vector<Factor> determinant_factors(Model& model) {
  std::vector<Factor> out;
  add_matrix_factors(model, model.fx, "Fx", out);
  add_matrix_factors(model, model.fq, "Fq", out);
  auto names = model.var_names();
  for (size_t i = 0; i < model.user_factors.size(); ++i)
    out.push_back({model.user_factors[i], model.user_factor_text[i],
                   "user-supplied (line " + std::to_string(model.user_factor_lines[i]) + ")",
                   "user " + std::to_string(i + 1)});
  return out;
}

}  // namespace aspects
