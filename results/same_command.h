// Whether two certified commands of one pose (point_command.h), from two solution boxes
// that both contain the pose, are one solution of f(x, ·) = 0. Neighbouring boxes share a
// face, and a pose on it has its command certified once in each box: `aspects query` lists
// it once when this proves it one, and says so when neither this nor the opposite is proved.
#pragma once

#include <vector>

#include "hansen_sengupta.h"
#include "model/model_eval.h"
#include "results/point_command.h"

namespace aspects {

enum class SameCommand {
  // Proved one solution: iteration (9) at the pose proves that f(x, ·) = 0 has a unique
  // root in a box holding both enclosures (each periodic command of the second shifted by
  // whole turns, the model being 2π-periodic in it), so both enclose that root.
  Same,
  // Proved two solutions: the enclosures are disjoint in some command (a periodic one for
  // every shift by whole turns).
  Distinct,
  Unknown,  // neither proved
};

// `a` and `b`: certified commands (command order) of `pose` (pose order).
SameCommand same_command(ModelEvaluator& ev, const std::vector<double>& pose,
                         const PointCommand& a, const PointCommand& b, double tau,
                         HsWorkspace& ws);

}  // namespace aspects
