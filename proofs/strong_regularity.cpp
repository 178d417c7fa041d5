#include "strong_regularity.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "certificate_grid.h"
#include "preconditioner.h"

namespace aspects {

namespace {

// M = C·[A], outward; false when an entry is unbounded.
bool precondition(const std::vector<double>& C, const IMatrix& A, IMatrix& M) {
  const int n = A.rows();
  if (M.rows() != n) M = IMatrix(n, n);
  Interval term;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      preconditioned_entry(C, A, i, j, M(i, j), term);
      if (!M(i, j).bounded() || M(i, j).empty()) return false;
    }
  return true;
}

// Row-wise strict dominance of M·diag(D): mig(M_ii)·D_i > Σ_{j≠i} mag(M_ij)·D_j, compared
// on the outward-rounded bounds (left end of the diagonal against the right end of the sum).
bool dominant(const IMatrix& M, const std::vector<double>& D) {
  const int n = M.rows();
  Interval term, off, diag;
  for (int i = 0; i < n; ++i) {
    mpfi_set_si(off.get(), 0);
    for (int j = 0; j < n; ++j) {
      mpfi_abs(term.get(), M(i, j).get());
      if (!D.empty()) mpfi_mul_d(term.get(), term.get(), D[j]);
      if (i == j)
        mpfi_set(diag.get(), term.get());
      else
        mpfi_add(off.get(), off.get(), term.get());
    }
    if (!(mpfr_cmp(&diag.get()->left, &off.get()->right) > 0)) return false;
  }
  return true;
}

// D = (I − G)^-1·1, G_ij = mag(M_ij) / mig(M_ii) off the diagonal (a choice in double:
// dominant() verifies it). Then (I − G)·D = 1 > 0, i.e. G·D < D: the scaled rows dominate.
bool column_weights(const IMatrix& M, std::vector<double>& D, bool grid) {
  const int n = M.rows();
  Eigen::MatrixXd G = Eigen::MatrixXd::Identity(n, n);
  for (int i = 0; i < n; ++i) {
    const Interval& d = M(i, i);
    double mig = d.lo_down() > 0 ? d.lo_down() : d.hi_up() < 0 ? -d.hi_up() : 0;
    if (!(mig > 0)) return false;
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      double mag = std::max(std::fabs(M(i, j).lo_down()), std::fabs(M(i, j).hi_up()));
      G(i, j) = -mag / mig;
    }
  }
  Eigen::VectorXd w = G.fullPivLu().solve(Eigen::VectorXd::Ones(n));
  D.resize(n);
  for (int j = 0; j < n; ++j) {
    if (!(w(j) > 0) || !std::isfinite(w(j))) return false;
    D[j] = w(j);
    // Format 3 codes a weight on the grid of [1, 2] (multiples of 2^-16): any positive
    // weight is sound, and dominant() tests the one recorded.
    const double g = grid ? grid::snap(D[j], 1.0, grid::step(1.0, 2.0), true) : 0;
    if (g > 0) D[j] = g;
  }
  return true;
}

}  // namespace

bool diagonally_dominant_after(const std::vector<double>& C, const IMatrix& A,
                               const std::vector<double>& D) {
  IMatrix M;
  return precondition(C, A, M) && dominant(M, D);
}

bool strongly_regular(const IMatrix& A, std::vector<double>* C_out, std::vector<double>* D_out,
                      bool grid) {
  std::vector<double> C, D(size_t(A.rows()), 1.0);
  thread_local IMatrix M;  // scratch: no MPFI allocation per test
  bool ok = approximate_inverse(A, C) && precondition(C, A, M) &&
            (dominant(M, D) || (column_weights(M, D, grid) && dominant(M, D)));
  if (C_out) *C_out = std::move(C);
  if (D_out) *D_out = std::move(D);
  return ok;
}

}  // namespace aspects
