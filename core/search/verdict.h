// What Prove decided about one box of Algorithm 1 (paper 4.2), as a value: the prover
// returns it, the search records it, and the bisector may act on it.
#pragma once

#include <array>
#include <cstdint>

namespace aspects {

enum class Verdict : uint8_t {
  Solution,            // P1, P2 and the inner test hold: a solution box
  NoExistence,         // P1: iteration (9) reached no strict inclusion
  WidePose,            // P1 failed, and the pose alone spreads the commands' image over
                       // half their box or more: a narrower pose is what could help
  NotCovering,         // P1 holds on an iterate that misses part of the cell's commands
  OutsideDomain,       // P1 holds, but the commands leave a non-periodic command's domain
  SingularFx,          // P2: Fx not proved regular on the reported box
  SingularFq,          // P2: Fq not proved regular on the reported box
  ConstraintBoundary,  // inner test: some constraint not certainly true on the box
};
constexpr int kVerdicts = 8;

const char* verdict_name(Verdict v);

using VerdictCounts = std::array<long, kVerdicts>;

}  // namespace aspects
