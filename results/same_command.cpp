#include "results/same_command.h"

#include <algorithm>
#include <cmath>

namespace aspects {

namespace {

// x + 2πm, rounded outward (MPFI at the working precision).
Interval shifted(long m, double x) {
  Interval t;
  mpfi_const_pi(t.get());
  mpfi_mul_si(t.get(), t.get(), 2 * m);
  mpfi_add_d(t.get(), t.get(), x);
  return t;
}

// [al, ah] and [bl, bh] + 2πm are disjoint, the shifted ends rounded outward.
bool apart(double al, double ah, double bl, double bh, long m) {
  if (m == 0) return ah < bl || bh < al;
  return ah < shifted(m, bl).lo_down() || shifted(m, bh).hi_up() < al;
}

// The whole turns that bring b's middle nearest a's (within rounding), in `turns`; false
// when there are too many to count in a long.
bool nearest_turns(double al, double ah, double bl, double bh, long& turns) {
  const double k = std::nearbyint((0.5 * (al + ah) - 0.5 * (bl + bh)) / (2 * M_PI));
  turns = std::fabs(k) < 1048576 ? long(k) : 0;
  return std::fabs(k) < 1048576;
}

}  // namespace

SameCommand same_command(ModelEvaluator& ev, const std::vector<double>& pose,
                         const PointCommand& a, const PointCommand& b, double tau,
                         HsWorkspace& ws) {
  const Model& m = ev.model();
  const int n = m.n();
  std::vector<long> turns(n, 0);
  for (int j = 0; j < n; ++j) {
    const double al = a.lo[j], ah = a.hi[j], bl = b.lo[j], bh = b.hi[j];
    if (!m.vars[m.command[j]].periodic) {
      if (apart(al, ah, bl, bh, 0)) return SameCommand::Distinct;
      continue;
    }
    if (!nearest_turns(al, ah, bl, bh, turns[j])) continue;
    // Two enclosures narrower than 1 apart at the nearest shift and at its two neighbours
    // are apart at every other shift: their middles are then more than 3π apart.
    const long k = turns[j];
    if (ah - al < 1 && bh - bl < 1 && apart(al, ah, bl, bh, k - 1) &&
        apart(al, ah, bl, bh, k) && apart(al, ah, bl, bh, k + 1))
      return SameCommand::Distinct;
  }
  // One box holding a and b (shifted): the hull, rounded outward, widened as
  // certified_command's box around the Newton root is (an enclosure a few ulps wide gives
  // no strict inclusion under rounding), and by the hull's own width.
  Box w(m.vars.size());
  std::vector<double> lo(n), hi(n);
  for (int j = 0; j < n; ++j) w[m.pose[j]].set_point(pose[j]);
  for (int j = 0; j < n; ++j) {
    double bl = b.lo[j], bh = b.hi[j];
    if (turns[j] != 0) {
      bl = shifted(turns[j], bl).lo_down();
      bh = shifted(turns[j], bh).hi_up();
    }
    lo[j] = std::min(a.lo[j], bl);
    hi[j] = std::max(a.hi[j], bh);
    const double r = 1e-9 * (1 + std::fabs(0.5 * lo[j] + 0.5 * hi[j])) + (hi[j] - lo[j]);
    w[m.command[j]].set_hull(lo[j] - r, hi[j] + r);  // each end moves out, or stays
  }
  ExistenceProof proof;
  if (prove_existence(ev, w, tau, 8, proof, ws) != Existence::Proved) return SameCommand::Unknown;
  // The root is unique in the last iterate, which must still hold both enclosures.
  for (int j = 0; j < n; ++j)
    if (!(proof.inflated[j].lo_down() <= lo[j] && hi[j] <= proof.inflated[j].hi_up()))
      return SameCommand::Unknown;
  return SameCommand::Same;
}

}  // namespace aspects
