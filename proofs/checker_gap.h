// A contractor that leaves a gap between what it removed and what it keeps. The
// certificate records the kept box, and check_cert refutes the closed slabs between the
// cell and that box (certificates/FORMAT.md); its enclosures differ from ours in the last
// bits, so each narrowed end moves back out by margins::contraction_gap. Only what the
// inner contractor proved empty is ever removed. With `grid`, each narrowed end then moves
// on out to the grid of the cell (proofs/certificate_grid.h), which format 3 records in a
// few bytes.
#pragma once

#include "search/contractor.h"

namespace aspects {

class CheckerGapContractor : public Contractor {
 public:
  explicit CheckerGapContractor(Contractor& inner, bool grid = false)
      : inner_(inner), grid_(grid) {}
  Refutation contract(Box& box) override;

 private:
  Contractor& inner_;
  bool grid_;
  Box cell_;  // scratch: the box before contraction
};

}  // namespace aspects
