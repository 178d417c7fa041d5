// Property P2 (paper 4.2.1, regularity test): an interval matrix [A] is strongly
// regular when C·[A] is strictly diagonally dominant for some real matrix C. Then every
// real A ∈ [A] is nonsingular. C is chosen in double (≈ mid([A])^-1, Eigen); the product
// and the dominance test are MPFI/MPFR with outward rounding, so any C gives a sound test.
#pragma once

#include <vector>

#include "interval.h"
#include "preconditioner.h"  // approximate_inverse: C

namespace aspects {

// True when C·[A] is strictly diagonally dominant (row-wise), computed outward.
bool diagonally_dominant_after(const std::vector<double>& C, const IMatrix& A);

// P2 for one matrix: picks C, then tests. `C_out`, if given, receives the C used.
bool strongly_regular(const IMatrix& A, std::vector<double>* C_out = nullptr);

}  // namespace aspects
