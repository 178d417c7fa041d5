#include "assembly_witness.h"

#include <algorithm>

#include "checker_margins.h"
#include "link.h"

namespace aspects {

namespace {

// Box b's pose part at the commands of `at`: f(X, q*) ∋ 0 is necessary for a zero in it.
// One evaluation; most candidates fail it on one of their two boxes.
bool image_holds_zero(ModelEvaluator& ev, const BoxStore& R, int b, Box& at,
                      std::vector<Interval>& y) {
  for (int v : ev.model().pose) at[v].set_hull(R.lo(b, v), R.hi(b, v));
  if (ev.equations(at, y) != EvalStatus::Defined) return false;
  for (const Interval& fi : y)
    if (!fi.contains_zero()) return false;
  return true;
}

// One Hansen–Sengupta sweep in x with intersection: an empty result proves there is no
// zero; otherwise `at` is contracted.
bool contract_pose(ModelEvaluator& ev, Box& at, std::vector<Interval>& y, HsWorkspace& ws) {
  const Model& m = ev.model();
  if (hansen_sengupta(ev, at, true, y, ws, true) != HsStatus::Ok) return false;
  for (size_t j = 0; j < m.pose.size(); ++j) at[m.pose[j]] = y[j];
  return true;
}

// Iteration (9) in x from the contracted box `at`. The image, widened by the checker's
// margin, must lie in box b (P1 applies there) and, on a non-periodic pose, in the inner
// declared domain (the same rule as check_cert's); so must [x~] there.
bool zero_in_box(ModelEvaluator& ev, const BoxStore& R, int b, const Box& at, double tau,
                 std::vector<Interval>& x, std::vector<double>& C, HsWorkspace& ws) {
  const Model& m = ev.model();
  ExistenceProof p;
  if (prove_existence(ev, at, tau, 12, p, ws, true) != Existence::Proved) return false;
  for (size_t j = 0; j < m.pose.size(); ++j) {
    const int v = m.pose[j];
    const Interval& t = p.inflated[j];
    const double margin = margins::image_widening() * (t.hi_up() - t.lo_down());
    if (p.image[j].lo_down() - margin < R.lo(b, v)) return false;
    if (p.image[j].hi_up() + margin > R.hi(b, v)) return false;
    const Variable& var = m.vars[v];
    if (!var.periodic && (t.lo_down() < var.inner_lo || t.hi_up() > var.inner_hi)) return false;
  }
  x = p.inflated;
  C = p.C;
  return true;
}

}  // namespace

bool prove_command_witness(ModelEvaluator& ev, const BoxStore& R, double tau, CommandWitness& w,
                           HsWorkspace& ws) {
  const Model& m = ev.model();
  Box at(R.nv());
  w.q.clear();
  for (int v : m.command) {
    double lo, hi;
    if (!inner_intersection(R.lo(w.a, v), R.hi(w.a, v), R.lo(w.b, v), R.hi(w.b, v), w.shift(v),
                            lo, hi))
      return false;
    const double q = std::min(std::max(lo + 0.5 * (hi - lo), lo), hi);
    w.q.push_back(q);
    at[v].set_point(q);
  }
  // f is 2π-periodic in the commands: q* serves box B as well as q* − 2πk would.
  // The tests run from the cheapest, each on both boxes before the next.
  Box at_b = at;
  std::vector<Interval> y;
  return image_holds_zero(ev, R, w.a, at, y) && image_holds_zero(ev, R, w.b, at_b, y) &&
         contract_pose(ev, at, y, ws) && contract_pose(ev, at_b, y, ws) &&
         zero_in_box(ev, R, w.a, at, tau, w.xa, w.ca, ws) &&
         zero_in_box(ev, R, w.b, at_b, tau, w.xb, w.cb, ws);
}

}  // namespace aspects
