#include "strong_regularity.h"

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

bool diagonally_dominant_after(const std::vector<double>& C, const IMatrix& A) {
  int n = A.rows();
  Interval entry, term, off, diag;
  for (int i = 0; i < n; ++i) {
    mpfi_set_si(off.get(), 0);
    for (int j = 0; j < n; ++j) {
      mpfi_set_si(entry.get(), 0);
      for (int k = 0; k < n; ++k) {
        mpfi_mul_d(term.get(), A(k, j).get(), C[size_t(i) * n + k]);
        mpfi_add(entry.get(), entry.get(), term.get());
      }
      if (!entry.bounded() || entry.empty()) return false;
      mpfi_abs(term.get(), entry.get());
      if (i == j)
        mpfi_set(diag.get(), term.get());
      else
        mpfi_add(off.get(), off.get(), term.get());
    }
    // mig(diag) is the left end of |diag|; it must exceed every possible off-sum.
    if (!(mpfr_cmp(&diag.get()->left, &off.get()->right) > 0)) return false;
  }
  return true;
}

bool strongly_regular(const IMatrix& A, std::vector<double>* C_out) {
  std::vector<double> C;
  if (!approximate_inverse(A, C)) return false;
  bool ok = diagonally_dominant_after(C, A);
  if (C_out) *C_out = std::move(C);
  return ok;
}

}  // namespace aspects
