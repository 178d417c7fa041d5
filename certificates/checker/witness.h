// witness.h — the check of a cuspidality witness `W <CSNC> <A> <B> <SHIFT>` (FORMAT.md,
// "Cuspidality witnesses"): two solution boxes of one CSNC whose poses overlap (box B
// shifted by 2πk, ends rounded inward) and whose commands are disjoint (modulo 2π on a
// periodic command, ends rounded outward). Independent of the solver's code.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "graph.h"
#include "ival.h"

namespace cc {

enum class WitnessCheck : uint8_t {
  Verified,
  NotOrdered,         // A < B is required
  NotSolutionBoxes,   // A or B is not a solution box
  OtherCsnc,          // A or B is not in the named CSNC
  ShiftNotPeriodic,   // a nonzero shift on a command or a non-periodic variable
  PosesDisjoint,      // the inner intersection of the pose parts is empty
  CommandsOverlap,    // no command is proved disjoint
};
const char* witness_message(WitnessCheck w);

struct WitnessVars {
  const std::vector<int>& pose;
  const std::vector<int>& command;
  const std::vector<bool>& periodic;
  const Ival& two_pi;
};

// csnc_of: the CSNC of each output box (-1 if none), from the csnc records.
WitnessCheck check_pose_witness(const OutBoxes& R, const std::vector<int32_t>& csnc_of, long c,
                                long a, long b, std::string_view shift, const WitnessVars& s);

}  // namespace cc
