// The margins the solver leaves so that an independent checker (certificates/FORMAT.md,
// check_cert), whose enclosures differ from ours in the last bits (another evaluation
// order, its own rounding of the preconditioner), confirms every recorded claim. They
// weaken nothing: each one makes a recorded claim *weaker* than what the solver proved.
#pragma once

#include <cmath>

namespace aspects::margins {

// Contraction records `P v lo hi`: the recorded interval is the contraction widened by
// this, relative to the cell's width and to the magnitude of the bound. The slabs
// outside it hold no solution with room to spare, so the checker's refutation of the
// closed slabs succeeds even where the contraction is tight to rounding level.
inline double contraction_gap(double cell_width, double bound) {
  return 1e-9 * cell_width + std::ldexp(1.0, -40) * std::max(1.0, std::fabs(bound));
}

// Solution records: the Hansen–Sengupta image [q] is widened by this fraction of the
// width of the inflated iterate [q~] (staying inside [q~] and the domain), so that the
// checker's image of the same operator lies inside the recorded one.
constexpr double image_widening = 1e-7;

// Factor signs: a sign is claimed only when the enclosure clears 0 by this fraction of
// its width (plus a tiny absolute amount).
constexpr double sign_clearance = 1e-9;
constexpr double sign_clearance_abs = 1e-300;

}  // namespace aspects::margins
