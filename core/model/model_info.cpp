#include "model/model_info.h"

namespace aspects {

const char* shape_name(MatrixShape s) {
  switch (s) {
    case MatrixShape::Diagonal: return "diagonal";
    case MatrixShape::LowerTriangular: return "lower triangular";
    case MatrixShape::UpperTriangular: return "upper triangular";
    case MatrixShape::Full: return "full";
  }
  return "?";
}

MatrixShape structural_shape(const Dag& dag, const std::vector<int>& m, int n) {
  bool lower = true, upper = true;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (m[i * n + j] == dag.zero()) continue;
      if (j > i) lower = false;
      if (j < i) upper = false;
    }
  if (lower && upper) return MatrixShape::Diagonal;
  if (lower) return MatrixShape::LowerTriangular;
  if (upper) return MatrixShape::UpperTriangular;
  return MatrixShape::Full;
}

namespace {
void print_pattern(const Model& m, const std::vector<int>& mat, const std::vector<int>& cols,
                   const char* title, std::ostream& out) {
  int n = m.n();
  out << title << " (" << shape_name(structural_shape(m.dag, mat, n)) << "), columns:";
  for (int j : cols) out << ' ' << m.vars[j].name;
  out << '\n';
  for (int i = 0; i < n; ++i) {
    out << "  eq" << (i + 1) << " ";
    for (int j = 0; j < n; ++j) out << ' ' << (mat[i * n + j] == m.dag.zero() ? '.' : '*');
    out << '\n';
  }
}
}  // namespace

void print_model_info(const Model& m, std::ostream& out) {
  out << "robot " << m.name << " (" << m.file << ")\n";
  out << "n = " << m.n() << " equations, " << m.pose.size() << " pose, " << m.command.size()
      << " command variables\n";
  out << "variables:\n";
  for (const auto& v : m.vars) {
    out << "  " << (v.kind == VarKind::Pose ? "pose    " : "command ") << v.name << " in "
        << v.domain.str();
    if (v.periodic) out << " periodic";
    if (v.domain.lo_down() == v.domain.hi_up()) out << " (fixed)";
    out << '\n';
  }
  out << "equations:\n";
  for (size_t i = 0; i < m.equation_text.size(); ++i)
    out << "  eq" << (i + 1) << ": " << m.equation_text[i] << '\n';
  print_pattern(m, m.fx, m.pose, "Fx = df/dx", out);
  print_pattern(m, m.fq, m.command, "Fq = df/dq", out);
  if (!m.user_factor_text.empty()) {
    out << "user factors:\n";
    for (size_t i = 0; i < m.user_factor_text.size(); ++i)
      out << "  line " << m.user_factor_lines[i] << ": " << m.user_factor_text[i] << '\n';
  }
  out << "expression DAG: " << m.dag.size() << " nodes (with derivatives)\n";
}

}  // namespace aspects
