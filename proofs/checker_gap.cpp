#include "checker_gap.h"

#include <cmath>

#include "certificate_grid.h"
#include "checker_margins.h"

namespace aspects {

Refutation CheckerGapContractor::contract(Box& box) {
  cell_ = box;
  Refutation r = inner_.contract(box);
  if (r) return r;
  for (size_t v = 0; v < box.size(); ++v) {
    double clo = cell_[v].lo_down(), chi = cell_[v].hi_up();
    double lo = box[v].lo_down(), hi = box[v].hi_up();
    double gap_lo = margins::contraction_gap(chi - clo, lo);
    double gap_hi = margins::contraction_gap(chi - clo, hi);
    lo = lo - gap_lo <= clo ? clo : std::nextafter(lo - gap_lo, -INFINITY);
    hi = hi + gap_hi >= chi ? chi : std::nextafter(hi + gap_hi, INFINITY);
    if (grid_) {
      const double u = grid::step(clo, chi, grid::kContractionBits);
      lo = std::max(clo, grid::snap(lo, clo, u, false));
      hi = std::min(chi, grid::snap(hi, chi, u, true));
    }
    // Below 53 bits the interval rounds these outward to the working precision: what it
    // holds is what the certificate records.
    box[v].set_hull(lo, hi);
  }
  return r;
}

}  // namespace aspects
