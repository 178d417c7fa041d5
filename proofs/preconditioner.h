// The preconditioning shared by P1 (proofs/hansen_sengupta.*) and P2
// (proofs/strong_regularity.*): a real matrix C ≈ mid([A])^-1 chosen in double (Eigen),
// and the products C·[A], C·[v] computed in MPFI (outward rounded). Any C keeps both
// proofs sound; a good one makes them succeed. (Arb's arb_mat_solve_preapprox: the
// caller's approximate inverse, the callee's proof.)
#pragma once

#include <vector>

#include "interval.h"

namespace aspects {

// Approximate inverse of mid([A]) in double, row major; false if mid([A]) is
// numerically singular or an entry is not finite (the caller then reports "not proved").
bool approximate_inverse(const IMatrix& A, std::vector<double>& C);

// out ⊇ Σ_k C(i, k)·[A](k, j), the entry (i, j) of C·[A]; `term` is scratch.
void preconditioned_entry(const std::vector<double>& C, const IMatrix& A, int i, int j,
                          Interval& out, Interval& term);

// out ⊇ Σ_k C(i, k)·[v]_k, the entry i of C·[v]; `term` is scratch.
void preconditioned_entry(const std::vector<double>& C, const std::vector<Interval>& v, int i,
                          Interval& out, Interval& term);

}  // namespace aspects
