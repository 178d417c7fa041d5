#include "contractor.h"

namespace aspects {

namespace {

double total_width(const Box& b) {
  double w = 0;
  for (const auto& x : b) w += x.width_up();
  return w;
}

}  // namespace

Refutation EquationContractor::contract(Box& box) {
  const Model& m = ev_.model();
  const int n = m.n();
  // AC3-like rounds over the equations, until a round gains less than 5% of the width.
  for (int round = 0; round < 20; ++round) {
    double before = total_width(box);
    for (int i = 0; i < n; ++i)
      if (!ev_.hc4(i, box)) return {Refutation::Equation, i};
    if (total_width(box) > 0.95 * before) break;
  }
  HsStatus s = hansen_sengupta(ev_, box, true, image_, ws_);
  if (s == HsStatus::NoSolution)
    return {Refutation::HansenSengupta, -1};  // no zero of f(x,·) for any x of the box
  if (s == HsStatus::Ok)
    for (int j = 0; j < n; ++j) box[m.command[j]] = image_[j];
  for (auto& x : box) round_out_to_doubles(x);
  return {};
}

}  // namespace aspects
