#include "preconditioner.h"

#include <Eigen/Dense>
#include <cmath>

namespace aspects {

bool approximate_inverse(const IMatrix& A, std::vector<double>& C) {
  int n = A.rows();
  Eigen::MatrixXd M(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double m = A(i, j).mid();
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

void preconditioned_entry(const std::vector<double>& C, const IMatrix& A, int i, int j,
                          Interval& out, Interval& term) {
  const int n = A.rows();
  mpfi_set_si(out.get(), 0);
  for (int k = 0; k < n; ++k) {
    mpfi_mul_d(term.get(), A(k, j).get(), C[size_t(i) * n + k]);
    mpfi_add(out.get(), out.get(), term.get());
  }
}

void preconditioned_entry(const std::vector<double>& C, const std::vector<Interval>& v, int i,
                          Interval& out, Interval& term) {
  const int n = int(v.size());
  mpfi_set_si(out.get(), 0);
  for (int k = 0; k < n; ++k) {
    mpfi_mul_d(term.get(), v[k].get(), C[size_t(i) * n + k]);
    mpfi_add(out.get(), out.get(), term.get());
  }
}

}  // namespace aspects
