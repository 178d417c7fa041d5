#include "solution_box.h"

#include <algorithm>

#include "certificate_grid.h"
#include "checker_margins.h"
#include "strong_regularity.h"

namespace aspects {

SolutionBoxProver::SolutionBoxProver(ModelEvaluator& ev, ConstraintChecker& constraints,
                                     double tau, int max_iterations, bool grid)
    : ev_(ev), constraints_(constraints), m_(ev.model()), tau_(tau),
      max_iterations_(max_iterations), grid_(grid) {}

// IMAGE moved out to the grid of Q~ (format 3 codes it against Q~), unless that leaves
// the domain: then it stays as it is, and is recorded in full.
void SolutionBoxProver::on_grid(double& lo, double& hi, const Interval& q,
                                const Variable& var) const {
  const double a = q.lo_down(), b = q.hi_up(), u = grid::step(a, b);
  const double glo = grid::snap(lo, a, u, false), ghi = grid::snap(hi, b, u, true);
  const bool in_domain = var.periodic || (glo >= var.inner_lo && ghi <= var.inner_hi);
  if (glo >= a && ghi <= b && in_domain) lo = glo, hi = ghi;
}

bool SolutionBoxProver::covers_cell(const ExistenceProof& ex, const Box& cell) const {
  for (int j = 0; j < m_.n(); ++j)
    if (!ex.inflated[j].contains(cell[m_.command[j]])) return false;
  return true;
}

Verdict SolutionBoxProver::prove(const Box& cell, Box& reported, SolutionProof& proof) {
  const int n = m_.n();
  ExistenceProof& ex = proof.existence;
  const Box* grid = grid_ ? &cell : nullptr;  // Q~ is coded against the cell
  Existence e = prove_existence(ev_, cell, tau_, max_iterations_, ex, ws_, false, grid);
  if (e == Existence::PoseSpread) return Verdict::WidePose;
  if (e != Existence::Proved) return Verdict::NoExistence;
  // Coverage: when the iterate shrank below the cell, try once more from the hull of
  // both, so that the proved box contains the cell.
  if (!covers_cell(ex, cell)) {
    retry_ = cell;
    for (int j = 0; j < n; ++j) {
      int v = m_.command[j];
      mpfi_union(retry_[v].get(), cell[v].get(), ex.inflated[j].get());
    }
    if (prove_existence(ev_, retry_, tau_, 2, ex, ws_, false, grid) != Existence::Proved)
      return Verdict::NoExistence;
    if (!covers_cell(ex, cell)) return Verdict::NotCovering;
  }
  // Domain: a command outside its range is not a configuration of the robot. A periodic
  // command may cross its seam: f is 2π-periodic in it (checked by the parser), and the
  // box then stands for its values modulo 2π. The inner enclosure of the bounds, as the
  // checker demands (certificates/FORMAT.md).
  for (int j = 0; j < n; ++j) {
    const Variable& var = m_.vars[m_.command[j]];
    if (var.periodic) continue;
    if (ex.image[j].lo_down() < var.inner_lo || ex.image[j].hi_up() > var.inner_hi)
      return Verdict::OutsideDomain;
  }
  // A box whose pose misses the declared domain holds no configuration of the robot: it
  // may not count for the bound (possible only within rounding of the root cell).
  for (int v : m_.pose) {
    const Variable& var = m_.vars[v];
    if (var.periodic) continue;
    if (cell[v].hi_up() < var.inner_lo || cell[v].lo_down() > var.inner_hi)
      return Verdict::OutsideDomain;
  }
  // The reported commands: the image widened by a margin for the checker, still inside
  // [q~] and the domain.
  reported = cell;
  for (int j = 0; j < n; ++j) {
    int v = m_.command[j];
    const Interval& q = ex.inflated[j];
    double margin = margins::image_widening() * (q.hi_up() - q.lo_down());
    double lo = std::max(q.lo_down(), ex.image[j].lo_down() - margin);
    double hi = std::min(q.hi_up(), ex.image[j].hi_up() + margin);
    if (!m_.vars[v].periodic) {
      lo = std::max(lo, m_.vars[v].inner_lo);
      hi = std::min(hi, m_.vars[v].inner_hi);
    }
    if (grid_) on_grid(lo, hi, q, m_.vars[v]);
    ex.image[j].set_hull(lo, hi);
    round_out_to_doubles(ex.image[j]);
    reported[v] = ex.image[j];
  }
  // P2 on the reported box, not on the cell: the iterate may have moved.
  if (ev_.jacobian_x(reported, J_) != EvalStatus::Defined ||
      !strongly_regular(J_, &proof.cx, &proof.dx, grid_))
    return Verdict::SingularFx;
  if (ev_.jacobian_q(reported, J_) != EvalStatus::Defined ||
      !strongly_regular(J_, &proof.cq, &proof.dq, grid_))
    return Verdict::SingularFq;
  if (constraints_.evaluate(reported) != Truth::True) return Verdict::ConstraintBoundary;
  return Verdict::Solution;
}

}  // namespace aspects
