// Property P2 (paper 4.2.1, regularity test): an interval matrix [A] is regular when
// C·[A]·D is strictly diagonally dominant (row-wise) for some real matrix C and some
// positive diagonal D. Then every real A ∈ [A] is nonsingular (C·A·D is, for each).
// C is chosen in double (≈ mid([A])^-1, Eigen). D = 1 is the paper's strong regularity
// test; when it fails, D is the positive vector (I − G)^-1·1 with G the off-diagonal
// magnitudes of C·[A] divided by the diagonal's mignitudes: it exists exactly when
// ρ(G) < 1, a much weaker demand than every row sum of G below 1 when the columns have
// different scales (an angle with a long lever arm next to lengths). The product and the
// dominance test are MPFI with outward rounding, so any C and D give a sound test.
#pragma once

#include <vector>

#include "numerics/interval.h"
#include "preconditioner.h"  // approximate_inverse: C

namespace aspects {

// True when C·[A]·diag(D) is strictly diagonally dominant (row-wise), computed outward.
// An empty D stands for weights 1 (the paper's test).
bool diagonally_dominant_after(const std::vector<double>& C, const IMatrix& A,
                               const std::vector<double>& D = {});

// P2 for one matrix: picks C and D, then tests. `C_out` and `D_out`, if given, receive them.
// With `grid`, D is on the grid format 3 codes weights on (proofs/certificate_grid.h).
bool strongly_regular(const IMatrix& A, std::vector<double>* C_out = nullptr,
                      std::vector<double>* D_out = nullptr, bool grid = false);

}  // namespace aspects
