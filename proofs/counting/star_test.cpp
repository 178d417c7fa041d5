#include "counting/star_test.h"

#include "counting/paving.h"

#include <algorithm>

namespace aspects {

namespace {

// ψ over box z (its w-part: an enclosure of w over its u-part); false when undefined.
bool value(ModelEvaluator& ev, const FactorGradients& fg, const FactorGradients* atoms,
           const Chart& chart, const Box& z, const StarConstraint& c,
           std::vector<Interval>& values, Interval& psi) {
  if (c.kind == StarConstraint::AtomStrict || c.kind == StarConstraint::AtomClosed) {
    if (!atoms || !atoms->values(ev, z, values)) return false;
    psi = values[c.index];
    return true;
  }
  if (c.kind == StarConstraint::Factor) {
    if (!fg.values(ev, z, values)) return false;
    psi = values[c.index];
    if (c.sign < 0) mpfi_neg(psi.get(), psi.get());
    return true;
  }
  psi = z[chart.w[c.index]];
  if (c.kind == StarConstraint::WLower)
    mpfi_sub_d(psi.get(), psi.get(), c.bound);
  else
    mpfi_d_sub(psi.get(), c.bound, psi.get());
  return true;
}

// ∇ψ over z, from X = (∂_w f)^{-1} ∂_u f.
bool gradient(ModelEvaluator& ev, const FactorGradients& fg, const FactorGradients* atoms,
              const Chart& chart, const Box& z, const StarConstraint& c, const IMatrix& X,
              std::vector<Interval>& grad) {
  const int n = ev.n();
  if (c.kind == StarConstraint::AtomStrict || c.kind == StarConstraint::AtomClosed)
    return atoms && atoms->gradient(ev, chart, z, X, c.index, grad);
  if (c.kind == StarConstraint::Factor) {
    if (!fg.gradient(ev, chart, z, X, c.index, grad)) return false;
    if (c.sign < 0)
      for (auto& g : grad) mpfi_neg(g.get(), g.get());
    return true;
  }
  // ∇w_j = −X_j·: ψ = w_j − lo has gradient −X_j·, ψ = hi − w_j has X_j·.
  grad.resize(n);
  for (int k = 0; k < n; ++k) {
    grad[k] = X(c.index, k);
    if (c.kind == StarConstraint::WLower) mpfi_neg(grad[k].get(), grad[k].get());
  }
  return true;
}

// Narrows z's w-part to an enclosure of w over its u-part (a few contracting sweeps).
void narrow_w(ModelEvaluator& ev, const Chart& chart, Box& z, HsWorkspace& ws,
              std::vector<Interval>& image) {
  const int n = ev.n();
  for (int sweep = 0; sweep < 6; ++sweep) {
    double before = 0, after = 0;
    for (int j = 0; j < n; ++j) before += z[chart.w[j]].width_up();
    if (hansen_sengupta(ev, z, true, image, ws, false, &chart.w) != HsStatus::Ok)
      return;
    for (int j = 0; j < n; ++j) {
      z[chart.w[j]] = image[j];
      round_out_to_doubles(z[chart.w[j]]);
      after += z[chart.w[j]].width_up();
    }
    if (!(after < 0.5 * before)) return;
  }
}

}  // namespace

StarVerdict star_test(ModelEvaluator& ev, const FactorGradients& fg, const Chart& chart,
                      const Box& box, const std::vector<StarConstraint>& cs,
                      const std::vector<double>& v, const std::vector<Interval>& wv,
                      const StarLimits& limits, HsWorkspace& ws, long& boxes,
                      const FactorGradients* atoms) {
  const int n = ev.n();
  const size_t nc = cs.size();
  std::vector<Interval> values, grad, image;
  std::vector<Interval> psi(nc);
  Interval d, t;
  IMatrix X;
  // Every constraint > 0 at the centre, on its enclosure.
  Box centre = box;
  for (int k = 0; k < n; ++k) centre[chart.u[k]].set_point(v[k]);
  for (int j = 0; j < n; ++j) centre[chart.w[j]] = wv[j];
  for (size_t c = 0; c < nc; ++c)
    if (!value(ev, fg, atoms, chart, centre, cs[c], values, psi[c]) || !psi[c].certainly_pos()) {
      return StarVerdict::NotProved;
    }

  std::vector<Box> stack{box};
  std::vector<uint8_t> defined(nc);
  long paved = 0;
  while (!stack.empty()) {
    Box z = std::move(stack.back());
    stack.pop_back();
    ++boxes;
    if (++paved > limits.max_boxes) {
      return StarVerdict::NotProved;
    }
    narrow_w(ev, chart, z, ws, image);
    bool negative = false, strict_can_be_positive = true;
    const bool factors_defined = fg.values(ev, z, values);  // once for every factor constraint
    for (size_t c = 0; c < nc; ++c) {
      if (cs[c].kind == StarConstraint::Factor) {
        defined[c] = factors_defined;
        if (factors_defined) {
          psi[c] = values[cs[c].index];
          if (cs[c].sign < 0) mpfi_neg(psi[c].get(), psi[c].get());
        }
      } else {
        defined[c] = value(ev, fg, atoms, chart, z, cs[c], values, psi[c]);
      }
      if (!defined[c]) continue;
      negative = negative || psi[c].certainly_neg();
      if (strict_constraint(cs[c]) && psi[c].hi_up() <= 0)
        strict_can_be_positive = false;
    }
    if (negative) continue;  // some constraint < 0 on the whole sub-box
    bool cleared = true;
    bool have_x = false, x_ok = false;
    for (size_t c = 0; c < nc && cleared; ++c) {
      const bool strict = strict_constraint(cs[c]);
      if (!strict && !strict_can_be_positive) continue;       // case (ii) impossible here
      if (defined[c] && psi[c].certainly_pos()) continue;      // ≠ 0 on the sub-box
      if (!have_x) {
        have_x = true;
        x_ok = fg.implicit_jacobian(ev, chart, z, X);
      }
      cleared = false;
      if (!x_ok || !gradient(ev, fg, atoms, chart, z, cs[c], X, grad)) break;
      d.set_point(0.0);
      for (int k = 0; k < n; ++k) {
        mpfi_sub_d(t.get(), z[chart.u[k]].get(), v[k]);
        mpfi_mul(t.get(), t.get(), grad[k].get());
        mpfi_add(d.get(), d.get(), t.get());
      }
      cleared = d.certainly_neg();
    }
    if (cleared) continue;
    if (!bisect_widest_u(chart, box, std::move(z), limits.min_width, stack))
      return StarVerdict::NotProved;
  }
  return StarVerdict::StarShaped;
}

}  // namespace aspects
