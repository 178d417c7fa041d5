#include "model/double_eval.h"

#include <cmath>

namespace aspects {

namespace {

DInterval abs_of(const DInterval& a) {
  if (a.lo >= 0) return a;
  if (a.hi <= 0) return neg(a);
  return {0.0, std::max(-a.lo, a.hi)};
}

// a ∩= hull((a ∩ p) ∪ (a ∩ −p)), as core/model/backward.cpp's meet_symmetric.
bool meet_symmetric(DInterval& a, const DInterval& p) {
  DInterval plus = a, minus = a;
  bool has_plus = meet(plus, p), has_minus = meet(minus, neg(p));
  if (!has_plus && !has_minus) return false;
  a = !has_plus ? minus : !has_minus ? plus : hull(plus, minus);
  return true;
}

const DInterval kHalfLine{0.0, INFINITY};  // [0, +∞)

}  // namespace

DoubleEvaluator::DoubleEvaluator(const Dag& dag)
    : dag_(dag), v_(dag.size()), fwd_(dag.size()), consts_(dag.size()),
      trig_arg_(dag.size()), trig_sin_(dag.size()), trig_cos_(dag.size()),
      trig_ok_(dag.size(), 0) {
  for (int id = 0; id < dag.size(); ++id)
    if (dag.node(id).op == Op::Const) consts_[id] = to_dinterval(dag.constant_value(id));
  Interval pi;
  mpfi_const_pi(pi.get());
  pi_ = to_dinterval(pi);
  mpfi_mul_2ui(pi.get(), pi.get(), 1);
  two_pi_ = to_dinterval(pi);
}

void DoubleEvaluator::sin_cos_of(int arg_id, const DInterval& arg) {
  if (trig_ok_[arg_id] && same(trig_arg_[arg_id], arg)) return;
  if (!sincos_.enclose_doubles(arg.lo, arg.hi, trig_sin_[arg_id], trig_cos_[arg_id])) {
    // An end may be a multiple of π/2: MPFI's own sin and cos (rare).
    mpfi_arg_.set_hull(arg.lo, arg.hi);
    mpfi_sin(mpfi_sin_.get(), mpfi_arg_.get());
    mpfi_cos(mpfi_cos_.get(), mpfi_arg_.get());
    trig_sin_[arg_id] = to_dinterval(mpfi_sin_);
    trig_cos_[arg_id] = to_dinterval(mpfi_cos_);
  }
  trig_arg_[arg_id] = arg;
  trig_ok_[arg_id] = 1;
}

// As Evaluator::eval_pow for k > 0: each end's power by repeated outward products.
DInterval DoubleEvaluator::power(const DInterval& a, int k) {
  const DInterval base = k % 2 == 0 ? abs_of(a) : a;
  DInterval lo{base.lo, base.lo}, hi{base.hi, base.hi};
  DInterval plo = lo, phi = hi;
  for (int i = 1; i < k; ++i) {
    plo = mul(plo, lo);
    phi = mul(phi, hi);
  }
  return hull(plo, phi);
}

std::optional<EvalStatus> DoubleEvaluator::forward(const std::vector<int>& program,
                                                   const Box& box) {
  EvalStatus status = EvalStatus::Defined;
  box_.resize(box.size());
  for (int id : program) {
    if (id >= int(v_.size())) return std::nullopt;  // a node made after this evaluator
    const Node& n = dag_.node(id);
    DInterval& r = v_[id];
    const DInterval a = n.a >= 0 ? v_[n.a] : DInterval{0, 0};
    const DInterval b = n.b >= 0 ? v_[n.b] : DInterval{0, 0};
    switch (n.op) {
      case Op::Const: r = consts_[id]; break;
      case Op::Var:
        r = to_dinterval(box[n.k]);
        if (is_empty(r)) return std::nullopt;
        box_[n.k] = r;
        break;
      case Op::Add: r = add(a, b); break;
      case Op::Sub: r = sub(a, b); break;
      case Op::Mul: r = n.a == n.b ? sqr(a) : mul(a, b); break;
      case Op::Div:
        if (has_zero(b)) return std::nullopt;
        r = div(a, b);
        break;
      case Op::Min: r = {std::min(a.lo, b.lo), std::min(a.hi, b.hi)}; break;
      case Op::Max: r = {std::max(a.lo, b.lo), std::max(a.hi, b.hi)}; break;
      case Op::Neg: r = neg(a); break;
      case Op::Sqr: r = sqr(a); break;
      case Op::Pow:
        if (n.k <= 0) return std::nullopt;
        r = power(a, n.k);
        break;
      case Op::Sqrt:
        if (a.lo < 0) return std::nullopt;
        r = sqrt(a);
        break;
      case Op::Sin:
      case Op::Cos:
        sin_cos_of(n.a, a);
        r = n.op == Op::Sin ? trig_sin_[n.a] : trig_cos_[n.a];
        break;
      case Op::Abs: r = abs_of(a); break;
      case Op::Sign:
        if (a.lo > 0) {
          r = {1, 1};
        } else if (a.hi < 0) {
          r = {-1, -1};
        } else {
          status = EvalStatus::Partial;  // the kink may lie in the box (core/model/eval.cpp)
          r = a.lo == 0 && a.hi == 0 ? DInterval{0, 0} : DInterval{-1, 1};
        }
        break;
      case Op::Step:
        if (a.hi < b.lo) {
          r = {1, 1};
        } else if (a.lo > b.hi) {
          r = {0, 0};
        } else {
          status = EvalStatus::Partial;
          r = {0, 1};
        }
        break;
      default: return std::nullopt;  // tan, exp, log, asin, acos, atan: MPFI
    }
    if (!is_finite(r)) return std::nullopt;
  }
  return status;
}

std::optional<bool> DoubleEvaluator::hc4_revise(const std::vector<int>& program, int root,
                                                DInterval target, Box& box) {
  if (!forward(program, box)) return std::nullopt;
  for (int id : program) fwd_[id] = v_[id];
  if (!meet(v_[root], target)) return false;
  for (auto it = program.rbegin(); it != program.rend(); ++it) {
    const int id = *it;
    // As the MPFI pass: a node backward did not narrow has nothing new for its children.
    if (id != root && same(v_[id], fwd_[id]) && dag_.node(id).op != Op::Var) continue;
    switch (backward(id)) {
      case Step::Narrowed: break;
      case Step::Empty: return false;
      case Step::Unsupported: return std::nullopt;
    }
  }
  for (int id : program) {
    const Node& n = dag_.node(id);
    if (n.op == Op::Var && !same(box_[n.k], fwd_[id])) box[n.k].set_hull(box_[n.k].lo, box_[n.k].hi);
  }
  return true;
}

// The kernels of core/model/backward.cpp, in the same order with the same operations.
DoubleEvaluator::Step DoubleEvaluator::backward(int id) {
  const Node& n = dag_.node(id);
  DInterval& r = v_[id];
  if (is_empty(r)) return Step::Empty;
  DInterval dummy{0, 0};
  DInterval& a = n.a >= 0 ? v_[n.a] : dummy;
  DInterval& b = n.b >= 0 ? v_[n.b] : dummy;
  auto ok = [](bool nonempty) { return nonempty ? Step::Narrowed : Step::Empty; };
  switch (n.op) {
    case Op::Const: return Step::Narrowed;
    case Op::Var: return ok(meet(box_[n.k], r));
    case Op::Add: return ok(meet(a, sub(r, b)) && meet(b, sub(r, a)));
    case Op::Sub: return ok(meet(a, add(r, b)) && meet(b, sub(a, r)));
    case Op::Mul:
      if (n.a == n.b) return ok(meet(r, kHalfLine) && meet_symmetric(a, sqrt(r)));
      if (!has_zero(b) && !meet(a, div(r, b))) return Step::Empty;
      if (!has_zero(a) && !meet(b, div(r, a))) return Step::Empty;
      return Step::Narrowed;
    case Op::Div:
      if (!meet(a, mul(r, b))) return Step::Empty;
      if (!has_zero(r) && !meet(b, div(a, r))) return Step::Empty;
      return Step::Narrowed;
    case Op::Min: return ok(meet(a, {r.lo, INFINITY}) && meet(b, {r.lo, INFINITY}));
    case Op::Max: return ok(meet(a, {-INFINITY, r.hi}) && meet(b, {-INFINITY, r.hi}));
    case Op::Neg: return ok(meet(a, neg(r)));
    case Op::Sqr: return ok(meet(r, kHalfLine) && meet_symmetric(a, sqrt(r)));
    case Op::Pow:
      if (n.k < 0) return Step::Narrowed;  // weak but sound, as bwd_pow
      return Step::Unsupported;            // k-th roots: MPFR
    case Op::Sqrt: return ok(meet(r, kHalfLine) && meet(a, sqr(r)));
    case Op::Abs: return ok(meet(r, kHalfLine) && meet_symmetric(a, r));
    case Op::Sin:
    case Op::Cos:
      // Skipped when narrowed by less than a tenth, as in Evaluator::backward.
      if (width_up(r) >= 0.9 * width_up(fwd_[id])) return Step::Narrowed;
      return project_periodic(n.op == Op::Sin, r, a);
    case Op::Tan:
    case Op::Sign:
    case Op::Step: return Step::Narrowed;
    default: return Step::Unsupported;
  }
}

// a ∩= {t : sin t ∈ r} (or cos), as core/model/backward.cpp's project_periodic.
DoubleEvaluator::Step DoubleEvaluator::project_periodic(bool is_sin, DInterval& r, DInterval& a) {
  if (!meet(r, {-1, 1})) return Step::Empty;
  double lo_lo, lo_hi, hi_lo, hi_hi;  // bounds of asin or acos at r's lower and upper end
  DInterval base;
  if (is_sin) {
    arb_.asin(r.lo, lo_lo, lo_hi);
    arb_.asin(r.hi, hi_lo, hi_hi);
    base = {lo_lo, hi_hi};
  } else {
    arb_.acos(r.lo, lo_lo, lo_hi);
    arb_.acos(r.hi, hi_lo, hi_hi);
    base = {hi_lo, lo_hi};
  }
  if (!is_finite(base)) return Step::Unsupported;
  const double period = 6.283185307179586;
  const double kmin = std::floor(a.lo / period) - 1, kmax = std::ceil(a.hi / period) + 1;
  if (kmax - kmin > 8) return Step::Narrowed;  // a spans many periods: nothing to gain
  DInterval acc{0, 0};
  bool empty = true;
  for (double k = kmin; k <= kmax; ++k) {
    for (int branch = 0; branch < 2; ++branch) {
      double plo = base.lo, phi = base.hi;
      if (branch == 1) {
        plo = (is_sin ? M_PI : 0) - base.hi;
        phi = (is_sin ? M_PI : 0) - base.lo;
      }
      plo += period * k;
      phi += period * k;
      const double slack = 1e-9 * (1 + std::fabs(plo) + std::fabs(phi));
      if (phi + slack < a.lo || plo - slack > a.hi) continue;
      DInterval piece = branch == 0 ? base : is_sin ? sub(pi_, base) : neg(base);
      piece = add(piece, mul(two_pi_, {k, k}));
      if (!meet(piece, a)) continue;
      acc = empty ? piece : hull(acc, piece);
      empty = false;
    }
  }
  if (empty) return Step::Empty;
  return meet(a, acc) ? Step::Narrowed : Step::Empty;
}

}  // namespace aspects
