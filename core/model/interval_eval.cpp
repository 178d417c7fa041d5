#include "model/interval_eval.h"

#include <stdexcept>

#include "numerics/evaluator_ops.h"

namespace aspects {

template <class I>
IntervalEvaluator<I>::IntervalEvaluator(const Dag& dag) : dag_(dag) {
  fit_to_dag();
}

template <class I>
void IntervalEvaluator<I>::fit_to_dag() {
  const size_t old_size = v_.size(), size = size_t(dag_.size());
  for (std::vector<I>* a : {&v_, &fwd_, &trig_arg_, &trig_sin_, &trig_cos_}) a->resize(size);
  trig_ok_.resize(size, 0);
  for (size_t id = old_size; id < size; ++id) {
    const Node& n = dag_.node(int(id));
    if (n.op != Op::Const) continue;
    if (size_t(n.k) >= consts_.size()) consts_.resize(size_t(n.k) + 1);
    iops::assign(consts_[n.k], dag_.constant_value(int(id)));
  }
}

template <class I>
const I& IntervalEvaluator<I>::sin_cos_of(int arg_id, const I& arg, Op op) {
  if (!trig_ok_[arg_id] || !iops::same_ends(trig_arg_[arg_id], arg)) {
    sincos_.enclose(arg, trig_sin_[arg_id], trig_cos_[arg_id]);
    iops::assign(trig_arg_[arg_id], arg);
    trig_ok_[arg_id] = 1;
  }
  return op == Op::Sin ? trig_sin_[arg_id] : trig_cos_[arg_id];
}

// a^k via the ends of |a| (k even) or a (k odd), where the power is monotone; each end's
// power is a product of point intervals rounded outward, so the hull encloses the range.
// k < 0: its inverse.
template <class I>
bool IntervalEvaluator<I>::power(I& r, const I& a, int k) {
  const int m = k < 0 ? -k : k;
  I& base = t1_;
  if (m % 2 == 0)
    iops::abs(base, a);
  else
    iops::assign(base, a);
  I& lo = t2_;
  I& hi = t3_;
  I& acc = t4_;
  iops::set_lower_end(lo, base);
  iops::set_upper_end(hi, base);
  iops::assign(acc, lo);
  for (int i = 1; i < m; ++i) iops::mul(acc, acc, lo);
  iops::assign(lo, acc);
  iops::assign(acc, hi);
  for (int i = 1; i < m; ++i) iops::mul(acc, acc, hi);
  iops::hull(r, lo, acc);
  return k > 0 || iops::inv(r, r);
}

// sqrt and log on [0, +∞], asin and acos on [−1, 1]: Partial where the argument leaves
// the domain (log also at 0), Undefined (an empty value) where it lies outside.
template <class I>
typename IntervalEvaluator<I>::NodeEval IntervalEvaluator<I>::on_domain(Op op, I& r, const I& a) {
  I& domain = t1_;
  I& inside = t2_;
  if (op == Op::Sqrt || op == Op::Log)
    iops::set_half_line(domain);
  else
    iops::set_unit(domain);
  NodeEval e = NodeEval::Defined;
  switch (iops::restrict_to(inside, a, domain)) {
    case iops::Restriction::Whole: break;
    case iops::Restriction::Part: e = NodeEval::Partial; break;
    case iops::Restriction::Declined: return NodeEval::Declined;
  }
  if (op == Op::Log && iops::contains_zero(a)) e = NodeEval::Partial;
  if (iops::empty(inside)) {
    iops::assign(r, inside);
    return NodeEval::Undefined;
  }
  bool done = false;
  switch (op) {
    case Op::Sqrt:
      iops::sqrt(r, inside);
      done = true;
      break;
    case Op::Log: done = iops::log(r, inside); break;
    case Op::Asin: done = iops::asin(r, inside); break;
    case Op::Acos: done = iops::acos(r, inside); break;
    default: throw std::logic_error("on_domain: not a function with a domain");
  }
  return done ? e : NodeEval::Declined;
}

// sign and step arise only as derivatives of abs, min and max. Where the kink may lie in
// the box the classical derivative may not exist there: Partial, so that no proof (P1,
// P2, P3, a factor's sign) rests on a generalized derivative, the rule check_cert applies
// too (robots/README.md). The value stays a sound hull.
template <class I>
typename IntervalEvaluator<I>::NodeEval IntervalEvaluator<I>::sign_or_step(const Node& n, I& r,
                                                                           const I& a,
                                                                           const I* b) {
  if (n.op == Op::Sign) {
    if (const int s = iops::sign_of(a)) {
      iops::set_int(r, s);
      return NodeEval::Defined;
    }
    if (iops::is_zero(a))
      iops::set_int(r, 0);
    else
      iops::set_unit(r);
    return NodeEval::Partial;
  }
  if (iops::certainly_below(a, *b)) {
    iops::set_int(r, 1);
    return NodeEval::Defined;
  }
  if (iops::certainly_above(a, *b)) {
    iops::set_int(r, 0);
    return NodeEval::Defined;
  }
  iops::set_int_range(r, 0, 1);
  return NodeEval::Partial;
}

template <class I>
typename IntervalEvaluator<I>::NodeEval IntervalEvaluator<I>::forward_node(int id,
                                                                           const Box& box) {
  const Node& n = dag_.node(id);
  I& r = v_[id];
  const I* a = n.a >= 0 ? &v_[n.a] : nullptr;
  const I* b = n.b >= 0 ? &v_[n.b] : nullptr;
  if ((a && iops::may_be_empty(*a)) || (b && iops::may_be_empty(*b))) {
    iops::assign(r, (a && iops::may_be_empty(*a)) ? *a : *b);  // stays empty
    return NodeEval::Undefined;
  }
  NodeEval e = NodeEval::Defined;
  bool done = true;  // false: a primitive declined
  switch (n.op) {
    case Op::Const: iops::assign(r, consts_[n.k]); break;
    case Op::Var: done = iops::load(r, box[n.k]); break;
    case Op::Add: iops::add(r, *a, *b); break;
    case Op::Sub: iops::sub(r, *a, *b); break;
    case Op::Mul:
      if (n.a == n.b)
        iops::sqr(r, *a);
      else
        iops::mul(r, *a, *b);
      break;
    case Op::Div:
      if (iops::contains_zero(*b)) e = NodeEval::Partial;
      done = iops::div(r, *a, *b);
      break;
    case Op::Min: iops::min_of(r, *a, *b); break;
    case Op::Max: iops::max_of(r, *a, *b); break;
    case Op::Neg: iops::neg(r, *a); break;
    case Op::Sqr: iops::sqr(r, *a); break;
    case Op::Pow:
      if (n.k < 0 && iops::contains_zero(*a)) e = NodeEval::Partial;
      done = power(r, *a, n.k);
      break;
    case Op::Sqrt:
    case Op::Log:
    case Op::Asin:
    case Op::Acos: e = on_domain(n.op, r, *a); break;
    case Op::Sin:
    case Op::Cos: iops::assign(r, sin_cos_of(n.a, *a, n.op)); break;
    case Op::Tan:
      done = iops::tan(r, *a);
      if (done && !iops::bounded(r)) e = NodeEval::Partial;  // a pole of tan lies in a
      break;
    case Op::Exp: done = iops::exp(r, *a); break;
    case Op::Abs: iops::abs(r, *a); break;
    case Op::Atan: done = iops::atan(r, *a); break;
    case Op::Sign:
    case Op::Step: e = sign_or_step(n, r, *a, b); break;
  }
  if (!done || e == NodeEval::Declined) return NodeEval::Declined;
  switch (iops::sanitize(r)) {
    case iops::Sanity::Kept: break;
    case iops::Sanity::MadeEntire:
      if (e == NodeEval::Defined) e = NodeEval::Partial;
      break;
    case iops::Sanity::Declined: return NodeEval::Declined;
  }
  return e;
}

template <class I>
std::optional<EvalStatus> IntervalEvaluator<I>::forward(const std::vector<int>& program,
                                                        const Box& box) {
  if (!program.empty() && program.back() >= int(v_.size())) fit_to_dag();
  EvalStatus status = EvalStatus::Defined;
  for (int id : program) {
    switch (forward_node(id, box)) {
      case NodeEval::Defined: break;
      case NodeEval::Partial:
        if (status == EvalStatus::Defined) status = EvalStatus::Partial;
        break;
      case NodeEval::Undefined: status = EvalStatus::Undefined; break;
      case NodeEval::Declined: return std::nullopt;
    }
  }
  return status;
}

template <class I>
std::optional<bool> IntervalEvaluator<I>::hc4_revise(const std::vector<int>& program, int root,
                                                     const I& target, Box& box) {
  const std::optional<EvalStatus> status = forward(program, box);
  if (!status) return std::nullopt;
  if (*status == EvalStatus::Undefined) return false;
  for (int id : program) iops::assign(fwd_[id], v_[id]);
  if (!iops::meet(v_[root], target)) return false;
  for (auto it = program.rbegin(); it != program.rend(); ++it) {
    const int id = *it;
    // A node the backward pass did not narrow has nothing new to tell its children
    // (skipping a projection is always sound: it only contracts less).
    if (id != root && iops::same_ends(v_[id], fwd_[id]) && dag_.node(id).op != Op::Var) continue;
    switch (backward(id)) {
      case Projection::Done: break;
      case Projection::Empty: return false;
      case Projection::Declined: return std::nullopt;
    }
  }
  for (int id : program) {
    const Node& n = dag_.node(id);
    if (n.op == Op::Var) iops::store_narrowed(box[n.k], v_[id], fwd_[id]);
  }
  return true;
}

// Projects node id's (already narrowed) value onto its children with the operation's
// kernel (core/model/backward.h). A variable's value goes back to the box at the end.
template <class I>
Projection IntervalEvaluator<I>::backward(int id) {
  const Node& n = dag_.node(id);
  I& r = v_[id];
  if (iops::empty(r)) return Projection::Empty;
  I* a = n.a >= 0 ? &v_[n.a] : nullptr;
  I* b = n.b >= 0 ? &v_[n.b] : nullptr;
  BackwardScratch<I>& s = bwd_;
  switch (n.op) {
    case Op::Const:
    case Op::Var: return Projection::Done;
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
      if (iops::width(r) >= 0.9 * iops::width(fwd_[id])) return Projection::Done;
      return n.op == Op::Sin ? bwd_sin(r, *a, s) : bwd_cos(r, *a, s);
    case Op::Tan:
      // The range check done by the parent's intersection is the (sound) projection kept.
    case Op::Sign:
    case Op::Step: return Projection::Done;
  }
  throw std::logic_error("backward: unknown op");
}

template class IntervalEvaluator<Interval>;
template class IntervalEvaluator<DInterval>;

}  // namespace aspects
