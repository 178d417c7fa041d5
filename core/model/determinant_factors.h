// Factors d1..dp of det Fx · det Fq used by the separation of paper 4.4.2. Defaults are
// det Fx and det Fq themselves (always sound). A structurally diagonal or triangular
// Jacobian has its determinant equal to the product of its diagonal entries, so those
// entries are used instead (the RRRRR's Fq needs this). User factors from the model
// (`factor EXPR`) are appended and recorded as user-supplied: they are sound only if
// they vanish solely at singular configurations.
#pragma once

#include <vector>

#include "model/model.h"

namespace aspects {

// Symbolic determinant of an n×n matrix of DAG nodes (cofactor expansion).
int symbolic_determinant(Dag& dag, const std::vector<int>& m, int n);

// Builds the factor list (adds the needed nodes to model.dag).
std::vector<Factor> determinant_factors(Model& model);

}  // namespace aspects
