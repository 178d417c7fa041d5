#include "witness.h"

#include <algorithm>
#include <cmath>

namespace cc {

const char* witness_message(WitnessCheck w) {
  switch (w) {
    case WitnessCheck::Verified:
      return "verified";
    case WitnessCheck::NotOrdered:
      return "witness needs A < B";
    case WitnessCheck::NotSolutionBoxes:
      return "witness boxes are not both solution boxes";
    case WitnessCheck::OtherCsnc:
      return "witness boxes are not both in the named CSNC";
    case WitnessCheck::ShiftNotPeriodic:
      return "witness shift on a command or a non-periodic variable";
    case WitnessCheck::PosesDisjoint:
      return "witness poses do not overlap";
    case WitnessCheck::CommandsOverlap:
      return "witness commands are not disjoint";
  }
  return "?";
}

namespace {

int shift_value(char c) {
  if (c == '+') return 1;
  if (c == '-') return -1;
  return 0;
}

// [al, ah] meets [bl, bh] + 2πk (the shifted ends rounded inward).
bool inner_meet(double al, double ah, double bl, double bh, int k, const Ival& two_pi) {
  if (k != 0) {
    Ival t;
    shift_by_periods(t, two_pi, k, bl);
    bl = t.hi();
    shift_by_periods(t, two_pi, k, bh);
    bh = t.lo();
  }
  return std::max(al, bl) <= std::min(ah, bh);
}

// [al, ah] ∩ ([bl, bh] + 2πm) = ∅ for every integer m: for one m, b + 2πm lies strictly
// above a and b + 2π(m − 1) strictly below it (the shifted ends rounded outward). The
// candidates m are chosen in double arithmetic; only the MPFI comparisons decide.
bool disjoint_mod_period(double al, double ah, double bl, double bh, const Ival& two_pi) {
  const double guess = std::ceil((ah - bl) / (2 * M_PI));
  if (!(std::fabs(guess) < 1048576)) return false;
  Ival t;
  for (long m = long(guess) - 1; m <= long(guess) + 1; ++m) {
    shift_by_periods(t, two_pi, int(m), bl);
    if (!(ah < t.lo())) continue;
    shift_by_periods(t, two_pi, int(m - 1), bh);
    if (t.hi() < al) return true;
  }
  return false;
}

}  // namespace

WitnessCheck check_pose_witness(const OutBoxes& R, const std::vector<int32_t>& csnc_of, long c,
                                long a, long b, std::string_view shift, const WitnessVars& s) {
  if (!(a < b)) return WitnessCheck::NotOrdered;
  if (!R.solution[a] || !R.solution[b]) return WitnessCheck::NotSolutionBoxes;
  if (csnc_of[a] != c || csnc_of[b] != c) return WitnessCheck::OtherCsnc;
  for (int v : s.command)
    if (shift[v] != '0') return WitnessCheck::ShiftNotPeriodic;
  const double* A = R.box(a);
  const double* B = R.box(b);
  for (int v : s.pose) {
    const int k = shift_value(shift[v]);
    if (k != 0 && !s.periodic[v]) return WitnessCheck::ShiftNotPeriodic;
    if (!inner_meet(A[2 * v], A[2 * v + 1], B[2 * v], B[2 * v + 1], k, s.two_pi))
      return WitnessCheck::PosesDisjoint;
  }
  for (int v : s.command) {
    const double al = A[2 * v], ah = A[2 * v + 1], bl = B[2 * v], bh = B[2 * v + 1];
    const bool apart = s.periodic[v] ? disjoint_mod_period(al, ah, bl, bh, s.two_pi)
                                     : (ah < bl || bh < al);
    if (apart) return WitnessCheck::Verified;
  }
  return WitnessCheck::CommandsOverlap;
}

}  // namespace cc
