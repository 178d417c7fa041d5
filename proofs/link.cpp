#include "link.h"

#include "certificate_grid.h"

namespace aspects {

bool inner_intersection(double alo, double ahi, double blo, double bhi, int k, double& lo,
                        double& hi) {
  if (k != 0) {
    // b ± 2π is not a double: round its ends inward.
    Interval t;
    mpfi_const_pi(t.get());
    mpfi_mul_si(t.get(), t.get(), 2 * k);
    Interval e;
    mpfi_add_d(e.get(), t.get(), blo);
    blo = e.hi_up();
    mpfi_add_d(e.get(), t.get(), bhi);
    bhi = e.lo_down();
  }
  lo = std::max(alo, blo);
  hi = std::min(ahi, bhi);
  return lo <= hi;
}

namespace {
// A point of the grid of box A's interval `a` near x inside `in`; x when there is none.
double on_grid(double x, const Interval& in, const Interval& a) {
  const double r = a.lo_down(), u = grid::step(r, a.hi_up());
  for (bool up : {false, true}) {
    const double g = grid::snap(x, r, u, up);
    if (g >= in.lo_down() && g <= in.hi_up()) return g;
  }
  return x;
}
}  // namespace

bool certify_link(ModelEvaluator& ev, const BoxStore& R, const NeighborPair& pair, double tau,
                  LinkProof& proof, HsWorkspace& ws, bool grid) {
  const Model& m = ev.model();
  const int n = m.n();
  Box w(R.nv()), a(R.nv());
  for (int v = 0; v < R.nv(); ++v) a[v].set_hull(R.lo(pair.a, v), R.hi(pair.a, v));
  proof.witness.assign(n, 0.0);
  proof.common.resize(n);
  for (int v = 0; v < R.nv(); ++v) {
    double lo, hi;
    if (!inner_intersection(R.lo(pair.a, v), R.hi(pair.a, v), R.lo(pair.b, v), R.hi(pair.b, v),
                            pair.shift(v), lo, hi))
      return false;
    w[v].set_hull(lo, hi);
  }
  for (int j = 0; j < n; ++j) {
    int v = m.pose[j];
    double x = w[v].mid();  // a double inside the inner intersection
    if (grid) x = on_grid(x, w[v], a[v]);
    proof.witness[j] = x;
    w[v].set_point(x);
    proof.common[j] = w[m.command[j]];
  }
  const Box* ref = grid ? &a : nullptr;
  if (prove_existence(ev, w, tau, 12, proof.existence, ws, false, ref) != Existence::Proved)
    return false;
  for (int j = 0; j < n; ++j)
    if (!proof.common[j].contains(proof.existence.image[j])) return false;
  return true;
}

}  // namespace aspects
