// Human-readable description of a model: variables, domains, equations, and the
// sparsity pattern of the Jacobians Fx and Fq (`aspects info`).
#pragma once

#include <ostream>
#include <vector>

#include "model/model.h"

namespace aspects {

enum class MatrixShape { Diagonal, LowerTriangular, UpperTriangular, Full };
const char* shape_name(MatrixShape s);
// Structural shape of an n×n node matrix (a structurally zero entry is Dag::zero()).
MatrixShape structural_shape(const Dag& dag, const std::vector<int>& m, int n);

void print_model_info(const Model& m, std::ostream& out);

}  // namespace aspects
