// The margins the solver leaves so that an independent checker (certificates/FORMAT.md,
// check_cert), whose enclosures differ from ours in the last bits (another evaluation
// order, its own rounding of the preconditioner), confirms every recorded claim. They
// weaken nothing: each one makes a recorded claim *weaker* than what the solver proved.
//
// "The last bits" are those of the working precision: below 53 bits both programs round
// every operation far more coarsely than the binary64 numbers they record, so each margin
// is at least a fixed multiple of 2^-precision (at 53 bits the fixed values dominate and
// the certificates are those of a precision-independent rule).
#pragma once

#include <algorithm>
#include <cmath>

#include "numerics/interval.h"

namespace aspects::margins {

// 2^16 units in the last place of the working precision, relative (2^-37 at 53 bits,
// below the fixed margins; 2^-8 at 24 bits, where midpoints and enclosures differ more).
inline double precision_slack() { return std::ldexp(1.0, 16 - int(working_precision())); }

// Contraction records `P v lo hi`: the recorded interval is the contraction widened by
// this, relative to the cell's width and to the magnitude of the bound. The slabs
// outside it hold no solution with room to spare, so the checker's refutation of the
// closed slabs succeeds even where the contraction is tight to rounding level.
inline double contraction_gap(double cell_width, double bound) {
  double rel = std::max(1e-9, precision_slack());
  double abs = std::max(std::ldexp(1.0, -40), precision_slack() / 8);  // 2^-40 at 53 bits
  return rel * cell_width + abs * std::max(1.0, std::fabs(bound));
}

// Solution records: the Hansen–Sengupta image [q] is widened by this fraction of the
// width of the inflated iterate [q~] (staying inside [q~] and the domain), so that the
// checker's image of the same operator lies inside the recorded one.
inline double image_widening() { return std::max(1e-7, precision_slack()); }

// Factor signs: a sign is claimed only when the enclosure clears 0 by this fraction of
// its width (plus a tiny absolute amount).
inline double sign_clearance() { return std::max(1e-9, precision_slack()); }
constexpr double sign_clearance_abs = 1e-300;

}  // namespace aspects::margins
