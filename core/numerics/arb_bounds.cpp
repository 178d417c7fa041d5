#include "numerics/arb_bounds.h"

#include <arb.h>

namespace aspects {

namespace {
// 64 bits leave the ball's radius far below half an ulp of a double.
const slong kPrec = 64;
}  // namespace

struct ArbBounds::Balls {
  arb_t t, a, b;
  arf_t end;
  Balls() {
    arb_init(t);
    arb_init(a);
    arb_init(b);
    arf_init(end);
  }
  ~Balls() {
    arb_clear(t);
    arb_clear(a);
    arb_clear(b);
    arf_clear(end);
  }
  // lo <= every point of x <= hi.
  void bounds(const arb_t x, double& lo, double& hi) {
    arb_get_lbound_arf(end, x, kPrec);
    lo = arf_get_d(end, ARF_RND_FLOOR);
    arb_get_ubound_arf(end, x, kPrec);
    hi = arf_get_d(end, ARF_RND_CEIL);
  }
};

ArbBounds::ArbBounds() : b_(new Balls) {}

ArbBounds::ArbBounds(const ArbBounds&) : ArbBounds() {}

ArbBounds::~ArbBounds() = default;

void ArbBounds::sin_cos(double t, double& s_lo, double& s_hi, double& c_lo, double& c_hi) {
  arb_set_d(b_->t, t);
  arb_sin_cos(b_->a, b_->b, b_->t, kPrec);
  b_->bounds(b_->a, s_lo, s_hi);
  b_->bounds(b_->b, c_lo, c_hi);
}

void ArbBounds::asin(double t, double& lo, double& hi) {
  arb_set_d(b_->t, t);
  arb_asin(b_->a, b_->t, kPrec);  // an indeterminate ball (NaN ends) outside [−1, 1]
  b_->bounds(b_->a, lo, hi);
}

void ArbBounds::acos(double t, double& lo, double& hi) {
  arb_set_d(b_->t, t);
  arb_acos(b_->a, b_->t, kPrec);
  b_->bounds(b_->a, lo, hi);
}

}  // namespace aspects
