// "One command, two poses" (paper 3.2, a non-singular assembly-mode change): the existence
// proof of a candidate of find_command_witnesses. q* is the midpoint (a double) of the
// inner-rounded [q_A] ∩ ([q_B] + 2πk); for each box, iteration (9) in x at the point q*
// (Hansen–Sengupta with Fx, hansen_sengupta(in_pose)) must give H ⊂ int [x~] and H inside
// the box's pose part, so f(·, q*) has a zero there (unique in [x~]); P1 of the box then
// makes (x, q*) a point of its graph (q* ∈ IMAGE ⊆ Q~, f periodic in q for box B).
#pragma once

#include "search/box_store.h"
#include "aspects/cuspidality.h"
#include "hansen_sengupta.h"

namespace aspects {

bool prove_command_witness(ModelEvaluator& ev, const BoxStore& R, double tau, CommandWitness& w,
                           HsWorkspace& ws);

}  // namespace aspects
