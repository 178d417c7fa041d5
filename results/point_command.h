// The command of a pose inside one solution box S = ([x], [q]) (paper 4.1): κ_S(x), the
// unique q ∈ [q] with f(x, q) = 0 (P1). Newton on f(x, ·) = 0 in double from mid [q]
// gives an approximation; the Hansen–Sengupta test at the point x (iteration (9) of
// proofs/hansen_sengupta.*, with [x] = {x}) around it then proves a root q* ∈ H with
// H ⊆ [q]. Since κ_S(x) is the only root in [q], q* = κ_S(x): H encloses it.
#pragma once

#include <vector>

#include "hansen_sengupta.h"
#include "model/model_eval.h"

namespace aspects {

enum class PointCommandStatus {
  Certified,  // enclosure holds κ_S(x)
  NotProved,  // neither the Newton start nor the whole [q] gave H ⊆ [q] (near a singularity)
};

enum class PointCommandStart {
  Newton,    // proved around the double Newton root
  WholeBox,  // Newton failed; proved from the box's [q]
};

struct PointCommand {
  PointCommandStatus status = PointCommandStatus::NotProved;
  PointCommandStart start = PointCommandStart::Newton;
  std::vector<double> lo, hi;  // enclosure of κ_S(x), command order (when Certified)
  int newton_iterations = 0;
  double width() const;        // largest width over the commands
};

// `lo`, `hi`: the solution box in model order; `pose` in pose order, inside [x] (modulo 2π
// on periodic coordinates: f is evaluated at the given values, which is the same).
PointCommand certified_command(ModelEvaluator& ev, const double* lo, const double* hi,
                               const std::vector<double>& pose, double tau, HsWorkspace& ws);

}  // namespace aspects
