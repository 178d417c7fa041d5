#include "strong_regularity.h"

#include "preconditioner.h"

namespace aspects {

bool diagonally_dominant_after(const std::vector<double>& C, const IMatrix& A) {
  int n = A.rows();
  Interval entry, term, off, diag;
  for (int i = 0; i < n; ++i) {
    mpfi_set_si(off.get(), 0);
    for (int j = 0; j < n; ++j) {
      preconditioned_entry(C, A, i, j, entry, term);
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
