#include "model/eval.h"

#include <stdexcept>

#include "model/backward.h"
#include "numerics/interval_ends.h"

namespace aspects {

using ends::L;
using ends::R;
using ends::set_half_line_pos;
using ends::set_unit;

namespace {

// out = x ∩ dom; returns true when dom did not remove anything.
bool restrict_to(Interval& out, const Interval& x, const Interval& dom) {
  mpfi_intersect(out.get(), x.get(), dom.get());
  return mpfi_is_inside(x.get(), dom.get()) > 0;
}

}  // namespace

Evaluator::Evaluator(const Dag& dag)
    : dag_(dag),
      doubles_(double_fast_path() && working_precision() == 53
                   ? new DoubleEvaluator(dag)
                   : nullptr),
      v_(dag.size()), fwd_(dag.size()), trig_arg_(dag.size()), trig_sin_(dag.size()),
      trig_cos_(dag.size()), trig_ok_(dag.size(), 0) {
  mpfi_const_pi(two_pi_.get());
  mpfi_mul_2ui(two_pi_.get(), two_pi_.get(), 1);
}

const Interval& Evaluator::sin_cos_of(int arg_id, const Interval& arg, Op op) {
  Interval& last = trig_arg_[arg_id];
  bool same = trig_ok_[arg_id] && mpfr_equal_p(L(last), L(arg)) && mpfr_equal_p(R(last), R(arg));
  if (!same) {
    sincos_.enclose(arg, trig_sin_[arg_id], trig_cos_[arg_id]);
    mpfi_set(last.get(), arg.get());
    trig_ok_[arg_id] = 1;
  }
  return op == Op::Sin ? trig_sin_[arg_id] : trig_cos_[arg_id];
}

void Evaluator::eval_pow(Interval& out, const Interval& a, int k) {
  // x^|k| via the endpoints of |x| (even) or x (odd): the power is monotone there, and
  // each endpoint power is computed as an MPFI product, so the hull encloses the range.
  int m = k < 0 ? -k : k;
  bool even = (m % 2) == 0;
  Interval& base = t1_;
  if (even)
    mpfi_abs(base.get(), a.get());
  else
    mpfi_set(base.get(), a.get());
  Interval& lo = t2_;
  Interval& hi = t3_;
  mpfi_set_fr(lo.get(), L(base));
  mpfi_set_fr(hi.get(), R(base));
  Interval& acc = t4_;
  mpfi_set(acc.get(), lo.get());
  for (int i = 1; i < m; ++i) mpfi_mul(acc.get(), acc.get(), lo.get());
  mpfi_set(lo.get(), acc.get());
  mpfi_set(acc.get(), hi.get());
  for (int i = 1; i < m; ++i) mpfi_mul(acc.get(), acc.get(), hi.get());
  mpfi_union(out.get(), lo.get(), acc.get());
  if (k < 0) mpfi_inv(out.get(), out.get());
}

const Interval& Evaluator::value(int id) const {
  if (from_doubles_) {
    const DInterval d = doubles_->value(id);
    mpfi_interv_d(v_[id].get(), d.lo, d.hi);  // exact: both ends are doubles
  }
  return v_[id];
}

DInterval Evaluator::value_d(int id) const {
  if (from_doubles_) return doubles_->value(id);
  return to_dinterval(v_[id]);
}

EvalStatus Evaluator::forward(const std::vector<int>& program, const Box& box) {
  if (doubles_) {
    if (std::optional<EvalStatus> s = doubles_->forward(program, box)) {
      from_doubles_ = true;
      return *s;
    }
  }
  return forward_mpfi(program, box);
}

EvalStatus Evaluator::forward_mpfi(const std::vector<int>& program, const Box& box) {
  from_doubles_ = false;
  EvalStatus status = EvalStatus::Defined;
  auto partial = [&]() {
    if (status == EvalStatus::Defined) status = EvalStatus::Partial;
  };
  for (int id : program) {
    const Node& n = dag_.node(id);
    Interval& r = v_[id];
    const Interval* a = n.a >= 0 ? &v_[n.a] : nullptr;
    const Interval* b = n.b >= 0 ? &v_[n.b] : nullptr;
    if ((a && a->empty()) || (b && b->empty())) {
      mpfi_set(r.get(), (a && a->empty()) ? a->get() : b->get());  // stays empty
      status = EvalStatus::Undefined;
      continue;
    }
    switch (n.op) {
      case Op::Const: mpfi_set(r.get(), dag_.constant_value(id).get()); break;
      case Op::Var: mpfi_set(r.get(), box[n.k].get()); break;
      case Op::Add: mpfi_add(r.get(), a->get(), b->get()); break;
      case Op::Sub: mpfi_sub(r.get(), a->get(), b->get()); break;
      case Op::Mul:
        if (n.a == n.b)
          mpfi_sqr(r.get(), a->get());
        else
          mpfi_mul(r.get(), a->get(), b->get());
        break;
      case Op::Div:
        if (b->contains_zero()) partial();
        mpfi_div(r.get(), a->get(), b->get());
        break;
      case Op::Min:
        mpfr_min(L(r), L(*a), L(*b), MPFR_RNDD);
        mpfr_min(R(r), R(*a), R(*b), MPFR_RNDU);
        break;
      case Op::Max:
        mpfr_max(L(r), L(*a), L(*b), MPFR_RNDD);
        mpfr_max(R(r), R(*a), R(*b), MPFR_RNDU);
        break;
      case Op::Neg: mpfi_neg(r.get(), a->get()); break;
      case Op::Sqr: mpfi_sqr(r.get(), a->get()); break;
      case Op::Pow:
        if (n.k < 0 && a->contains_zero()) partial();
        eval_pow(r, *a, n.k);
        break;
      case Op::Sqrt:
      case Op::Log: {
        set_half_line_pos(t1_);
        if (!restrict_to(t2_, *a, t1_) || (n.op == Op::Log && a->contains_zero())) partial();
        if (t2_.empty()) {
          status = EvalStatus::Undefined;
          mpfi_set(r.get(), t2_.get());
          break;
        }
        if (n.op == Op::Sqrt)
          mpfi_sqrt(r.get(), t2_.get());
        else
          mpfi_log(r.get(), t2_.get());
        break;
      }
      case Op::Asin:
      case Op::Acos: {
        set_unit(t1_);
        if (!restrict_to(t2_, *a, t1_)) partial();
        if (t2_.empty()) {
          status = EvalStatus::Undefined;
          mpfi_set(r.get(), t2_.get());
          break;
        }
        if (n.op == Op::Asin)
          mpfi_asin(r.get(), t2_.get());
        else
          mpfi_acos(r.get(), t2_.get());
        break;
      }
      case Op::Sin:
      case Op::Cos:
        mpfi_set(r.get(), sin_cos_of(n.a, *a, n.op).get());
        break;
      case Op::Tan:
        mpfi_tan(r.get(), a->get());
        if (!r.bounded()) partial();  // a pole of tan lies in the argument
        break;
      case Op::Exp: mpfi_exp(r.get(), a->get()); break;
      case Op::Abs: mpfi_abs(r.get(), a->get()); break;
      case Op::Atan: mpfi_atan(r.get(), a->get()); break;
      // sign and step arise only as derivatives of abs, min and max. Where the kink may
      // lie in the box the classical derivative may not exist there: Partial, so that no
      // proof (P1, P2, P3, a factor's sign) rests on a generalized derivative, the rule
      // check_cert applies too (robots/README.md). The value stays a sound hull.
      case Op::Sign: {
        int s = certain_sign(*a);
        if (s != 0) {
          mpfi_set_si(r.get(), s);
          break;
        }
        partial();
        if (mpfr_zero_p(L(*a)) && mpfr_zero_p(R(*a)))
          mpfi_set_si(r.get(), 0);
        else
          set_unit(r);
        break;
      }
      case Op::Step:
        if (mpfr_less_p(R(*a), L(*b))) {
          mpfi_set_si(r.get(), 1);
        } else if (mpfr_greater_p(L(*a), R(*b))) {
          mpfi_set_si(r.get(), 0);
        } else {
          partial();
          mpfi_interv_si(r.get(), 0, 1);
        }
        break;
    }
    if (mpfi_nan_p(r.get())) {
      // Should not happen after the domain restrictions; stay sound if it does.
      r.set_entire();
      partial();
    }
  }
  return status;
}

bool Evaluator::hc4_revise(const std::vector<int>& program, int root, const Interval& target,
                           Box& box) {
  if (doubles_) {
    if (std::optional<bool> feasible =
            doubles_->hc4_revise(program, root, to_dinterval(target), box)) {
      from_doubles_ = true;
      return *feasible;
    }
  }
  if (forward_mpfi(program, box) == EvalStatus::Undefined) return false;
  for (int id : program) mpfi_set(fwd_[id].get(), v_[id].get());
  if (!v_[root].intersect(target)) return false;
  for (auto it = program.rbegin(); it != program.rend(); ++it) {
    int id = *it;
    // A node the backward pass did not narrow has nothing new to tell its children
    // (skipping a projection is always sound: it only contracts less).
    const Interval& v = v_[id];
    if (id != root && mpfr_equal_p(L(v), L(fwd_[id])) && mpfr_equal_p(R(v), R(fwd_[id])) &&
        dag_.node(id).op != Op::Var)
      continue;
    if (!backward(id, box)) return false;
  }
  return true;
}

// Projects node id's (already narrowed) value onto its children with the operation's
// kernel (core/model/backward.h): each intersects a child with a superset of {child values
// compatible with the parent's value}.
bool Evaluator::backward(int id, Box& box) {
  const Node& n = dag_.node(id);
  Interval& r = v_[id];
  if (r.empty()) return false;
  Interval* a = n.a >= 0 ? &v_[n.a] : nullptr;
  Interval* b = n.b >= 0 ? &v_[n.b] : nullptr;
  BackwardScratch& s = bwd_;
  switch (n.op) {
    case Op::Const: return true;
    case Op::Var: return box[n.k].intersect(r);
    case Op::Add: return bwd_add(r, *a, *b, s);
    case Op::Sub: return bwd_sub(r, *a, *b, s);
    case Op::Mul: return n.a == n.b ? bwd_sqr(r, *a, s) : bwd_mul(r, *a, *b, s);
    case Op::Div: return bwd_div(r, *a, *b, s);
    case Op::Min: return bwd_min(r, *a, *b, s);
    case Op::Max: return bwd_max(r, *a, *b, s);
    case Op::Neg: return bwd_neg(r, *a, s);
    case Op::Sqr: return bwd_sqr(r, *a, s);
    case Op::Pow: return bwd_pow(r, *a, n.k, s);
    case Op::Sqrt: return bwd_sqrt(r, *a, s);
    case Op::Exp: return bwd_exp(r, *a, s);
    case Op::Log: return bwd_log(r, *a, s);
    case Op::Abs: return bwd_abs(r, *a, s);
    case Op::Asin: return bwd_asin(r, *a, s);
    case Op::Acos: return bwd_acos(r, *a, s);
    case Op::Atan: return bwd_atan(r, *a, s);
    case Op::Sin:
    case Op::Cos:
      // The preimage costs an asin or acos and up to ten pieces; when the node narrowed
      // by less than a tenth it rarely pays (skipping only contracts less: sound).
      // RRRRR eps 0.1: 6 % less CPU for 1 % more boxes (bench/RESULTS.md).
      if (r.width_up() >= 0.9 * fwd_[id].width_up()) return true;
      if (n.op == Op::Sin) return bwd_sin(r, *a, two_pi_, s);
      return bwd_cos(r, *a, two_pi_, s);
    case Op::Tan:
      // The range check done by the parent's intersection is the (sound) projection kept.
      return true;
    case Op::Sign:
    case Op::Step:
      return true;
  }
  throw std::logic_error("backward: unknown op");
}

}  // namespace aspects
