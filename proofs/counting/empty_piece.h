// A piece proved empty by paving: in a chart over U (counting/chart.h), the class s has no
// point when every part of a paving of U has a factor whose enclosure s_i·g_i(S, W_S) is
// ≤ 0 (W_S an enclosure of w over S). Finer than one enclosure over the whole box, which
// the dependency problem widens past a factor's small value.
#pragma once

#include <cstdint>

#include "counting/factor_gradients.h"
#include "model/constraints.h"

namespace aspects {

enum class EmptyVerdict : uint8_t { Empty, NotProved };

// `box`: the cell's box U × W (a point of the piece is a solution in it; a part of U whose
// w(u) all leave W is cleared as holding none, as check_cert's paving clears it: a class cut
// off by a face of W is empty with no factor's sign to show). max_boxes: the paving's budget
// (check_cert allows more). `constraints` (or null): a part where a constraint is False holds
// no feasible point, and is cleared too.
EmptyVerdict prove_piece_empty(ModelEvaluator& ev, const FactorGradients& fg, const Chart& chart,
                               const Box& box, uint32_t cls, HsWorkspace& ws,
                               long max_boxes = 4000, ConstraintChecker* constraints = nullptr);

}  // namespace aspects
