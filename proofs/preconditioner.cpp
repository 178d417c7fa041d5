#include "preconditioner.h"

#include <Eigen/Dense>
#include <cmath>

#include "numerics/interval_ops.h"

namespace aspects {

template <class I>
bool approximate_inverse(const Matrix<I>& A, std::vector<double>& C) {
  int n = A.rows();
  Eigen::MatrixXd M(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double m = iops::mid(A(i, j));
      if (!std::isfinite(m)) return false;
      M(i, j) = m;
    }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(M);
  if (!lu.isInvertible()) return false;
  Eigen::MatrixXd inv = lu.inverse();
  C.resize(size_t(n) * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (!std::isfinite(inv(i, j))) return false;
      C[size_t(i) * n + j] = inv(i, j);
    }
  return true;
}

template <class I>
void preconditioned_entry(const std::vector<double>& C, const Matrix<I>& A, int i, int j, I& out,
                          I& term) {
  const int n = A.rows();
  iops::set_zero(out);
  for (int k = 0; k < n; ++k) {
    iops::mul_d(term, A(k, j), C[size_t(i) * n + k]);
    iops::add_to(out, term);
  }
}

template <class I>
void preconditioned_entry(const std::vector<double>& C, const std::vector<I>& v, int i, I& out,
                          I& term) {
  const int n = int(v.size());
  iops::set_zero(out);
  for (int k = 0; k < n; ++k) {
    iops::mul_d(term, v[k], C[size_t(i) * n + k]);
    iops::add_to(out, term);
  }
}

template bool approximate_inverse(const IMatrix&, std::vector<double>&);
template bool approximate_inverse(const DMatrix&, std::vector<double>&);
template void preconditioned_entry(const std::vector<double>&, const IMatrix&, int, int,
                                   Interval&, Interval&);
template void preconditioned_entry(const std::vector<double>&, const DMatrix&, int, int,
                                   DInterval&, DInterval&);
template void preconditioned_entry(const std::vector<double>&, const std::vector<Interval>&, int,
                                   Interval&, Interval&);
template void preconditioned_entry(const std::vector<double>&, const std::vector<DInterval>&, int,
                                   DInterval&, DInterval&);

}  // namespace aspects
