// The preconditioning shared by P1 (proofs/hansen_sengupta.*) and P2
// (proofs/strong_regularity.*): a real matrix C ≈ mid([A])^-1 chosen in double (Eigen),
// and the products C·[A], C·[v] computed in MPFI (outward rounded). Any C keeps both
// proofs sound; a good one makes them succeed. (Arb's arb_mat_solve_preapprox: the
// caller's approximate inverse, the callee's proof.)
#pragma once

#include <vector>

#include "numerics/interval.h"

namespace aspects {

// Approximate inverse of mid([A]) in double, row major; false if mid([A]) is
// numerically singular or an entry is not finite (the caller then reports "not proved").
// For Interval and for DInterval (53 bits) matrices.
template <class I>
bool approximate_inverse(const Matrix<I>& A, std::vector<double>& C);

// out ⊇ Σ_k C(i, k)·[A](k, j), the entry (i, j) of C·[A]; `term` is scratch.
template <class I>
void preconditioned_entry(const std::vector<double>& C, const Matrix<I>& A, int i, int j, I& out,
                          I& term);

// out ⊇ Σ_k C(i, k)·[v]_k, the entry i of C·[v]; `term` is scratch.
template <class I>
void preconditioned_entry(const std::vector<double>& C, const std::vector<I>& v, int i, I& out,
                          I& term);

}  // namespace aspects
