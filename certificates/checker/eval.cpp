// eval.cpp — trusted core: interval semantics (interval.h) of every node of the model language
// (statuses and modes in checker.h); its speed layer is eval_speed.cpp. Unbounded or NaN results
// become the entire line with status 1. HC4 backward steps intersect each child with a superset of
// its values compatible with the parent.
#include "checker.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace cc {

// The status of a variable's interval: 2 empty, 0 bounded, 1 unbounded.
static int var_status(const Ival& x) {
  if (x.empty()) return 2;
  return x.bounded() ? 0 : 1;
}

// A divisor (or the base of a negative power) that contains 0: the result is defined nowhere
// when it is [0, 0] (status 2), else nothing is known of it (the entire line, status 1).
static int pole(Ival& r, const Ival& d) {
  if (d.is_zero()) return 2;
  r.entire();
  return 1;
}

bool Evaluator::speed = true;

Evaluator::~Evaluator() = default;

Evaluator::Evaluator(const Model& m) : m_(m) {
  const size_t N = m.nodes.size();
  val_.resize(N);
  cval_.resize(N);
  der_.resize(N * m.vars.size());
  for (auto& d : der_) set_si(d, 0);  // entries of variables a node does not mention stay 0
  cstat_.assign(N, 0);
  st_.assign(N, 0);
  tc_of_.assign(N, -1);
  stamp_.assign(N, 0);
  seen_.resize(m.vars.size());
  changed_at_.assign(m.vars.size(), 0);
  int caches = 0;
  for (const Node& n : m.nodes)
    if ((n.op == Op::Sin || n.op == Op::Cos) && tc_of_[n.a] < 0) tc_of_[n.a] = caches++;
  tc_.resize(size_t(caches));
  const_pi(pi_);
  add(two_pi, pi_, pi_);
  // Constant sub-expressions are evaluated once, with their definedness status.
  for (size_t id = 0; id < N; ++id) {
    const Node& n = m.nodes[id];
    if (n.dep) continue;
    const Ival* a = n.a >= 0 ? &cval_[n.a] : nullptr;
    const Ival* b = n.b >= 0 ? &cval_[n.b] : nullptr;
    const int st = std::max(n.a >= 0 ? cstat_[n.a] : 0, n.b >= 0 ? cstat_[n.b] : 0);
    cstat_[id] = st;
    if (st < 2) cstat_[id] = std::max(st, apply(int(id), cval_[id], a, b));
  }
  all_eqs = closure(m, m.eqs);
  all_atoms = closure(m, m.atoms);
  for (int e : m.eqs) eq_prog.push_back(closure(m, {e}));
  for (int f : m.factors) factor_prog.push_back(closure(m, {f}));
}

bool Evaluator::constant(int id, Ival& out) const {
  if (m_.nodes[id].dep || cstat_[id] != 0) return false;
  out = cval_[id];
  return true;
}

void Evaluator::power(Ival& r, const Ival& a, int k) {
  const unsigned long m = (unsigned long)(k < 0 ? -k : k);
  if (m == 0) {
    set_si(r, 1);
    return;
  }
  // x^m is monotone in |x| (m even) or in x (m odd): power the ends with directed rounding.
  t4_ = a;
  if (m % 2 == 0) abs(t4_, a);
  pow_ui(r, t4_, m);
  if (k < 0) inv(r, r);  // callers guarantee 0 is not in a
}

// sin and cos of a, the last argument's kept per argument node: by MPFI, or by Arb
// (eval_speed.cpp).
void Evaluator::trig(bool cosine, int child, const Ival& a, Ival& r) {
  TrigCache& c = tc_[tc_of_[child]];
  if (!same(c.arg, Lo, a, Lo) || !same(c.arg, Hi, a, Hi)) {  // NaN: never equal
    if (speed) {
      arb_sincos(c, a);
    } else {
      apply_fn(Fn::Sin, c.sin, a);
      apply_fn(Fn::Cos, c.cos, a);
    }
    c.arg = a;
  }
  r = cosine ? c.cos : c.sin;
}

int Evaluator::apply(int id, Ival& r, const Ival* a, const Ival* b) {
  const Node& n = m_.nodes[id];
  int st = 0;
  switch (n.op) {
    case Op::Const:
      if (!set_str(r, m_.literals[n.k]))
        throw ModelError("malformed number '" + m_.literals[n.k] + "'");
      break;
    case Op::Pi: const_pi(r); break;
    case Op::Var: break;  // handled by eval()
    case Op::Add: add(r, *a, *b); break;
    case Op::Sub: sub(r, *a, *b); break;
    case Op::Mul:
      if (n.a == n.b) sqr(r, *a);
      else mul(r, *a, *b);
      break;
    case Op::Div:  // b ∋ 0: defined nowhere if b = [0, 0], else no information
      if (b->has_zero()) return pole(r, *b);
      div(r, *a, *b);
      break;
    case Op::Min: min(r, *a, *b); break;
    case Op::Max: max(r, *a, *b); break;
    case Op::Neg: neg(r, *a); break;
    case Op::Sqr: sqr(r, *a); break;
    case Op::Pow:
      if (n.k < 0 && a->has_zero()) return pole(r, *a);
      power(r, *a, n.k);
      break;
    case Op::Sqrt:  // on a ∩ [0, +inf]
      if (a->end_sign(Hi) < 0) return 2;
      st = a->end_sign(Lo) < 0;
      t1_ = *a;
      if (st) t1_.set_end(Lo, 0);
      sqrt(r, t1_);
      break;
    case Op::Log:
      if (a->end_sign(Hi) <= 0) return 2;
      if (a->end_sign(Lo) <= 0) {  // log on a ∩ (0, +inf]
        log_hi(r, *a);
        st = 1;
      } else {
        apply_fn(Fn::Log, r, *a);
      }
      break;
    case Op::Asin:
    case Op::Acos:
      if (cmp(*a, Hi, -1) < 0 || cmp(*a, Lo, 1) > 0) return 2;
      t1_.set(-1, 1);
      if (!is_inside(*a, t1_)) st = 1;
      intersect(t1_, *a, t1_);
      apply_fn(n.op == Op::Asin ? Fn::Asin : Fn::Acos, r, t1_);
      break;
    case Op::Exp: apply_fn(Fn::Exp, r, *a); break;
    case Op::Sin: trig(false, n.a, *a, r); break;
    case Op::Cos: trig(true, n.a, *a, r); break;
    case Op::Tan: apply_fn(Fn::Tan, r, *a); break;  // a pole inside: unbounded, st 1 below
    case Op::Abs: abs(r, *a); break;
    case Op::Atan: apply_fn(Fn::Atan, r, *a); break;
  }
  if (r.nan()) r.entire();
  if (!r.bounded()) return 1;
  return st;
}

// A node's status is the worst of its children's and its own; undefined children make it
// undefined (its value is then meaningless). Proof mode stops at 1, Refute mode at 2, Truth
// mode evaluates every node.
bool Evaluator::eval(const std::vector<int>& prog, const Ival* box, Mode mode) {
  charge(prog.size());
  if (speed) note_changes(box);
  for (int id : prog) {
    const Node& n = m_.nodes[id];
    Ival& r = val_[id];
    int& st = st_[id];
    if (!n.dep) {
      r = cval_[id];
      st = cstat_[id];
    } else if (!speed || !fresh(id)) {  // fresh: unchanged since (eval_speed.cpp)
      if (n.op == Op::Var) {
        r = box[n.k];
        st = var_status(r);
      } else {
        const Ival* b = n.b >= 0 ? &val_[n.b] : nullptr;
        st = std::max(st_[n.a], n.b >= 0 ? st_[n.b] : 0);
        if (st < 2) st = std::max(st, apply(id, r, &val_[n.a], b));
      }
      stamp_[id] = clock_;
    }
    if (mode != Mode::Truth && (st == 2 || (st == 1 && mode == Mode::Proof))) return false;
  }
  return true;
}

// An atom g >= 0 (> 0) is True when g is defined on the whole box with lo >= 0 (> 0), False
// when hi < 0 (<= 0) or g is defined nowhere; And/Or are min/max in False < Unknown < True.
int Evaluator::truth(int f) const {
  const Formula& F = m_.formulas[f];
  if (F.kind == Formula::Atom) {
    const Ival& g = val_[F.expr];
    if (st_[F.expr] == 2 || g.empty() || g.end_sign(Hi) < int(F.strict)) return 0;
    return st_[F.expr] == 0 && g.end_sign(Lo) >= int(F.strict) ? 2 : 1;
  }
  int t = F.kind == Formula::And ? 2 : 0;
  for (int k : F.kids) t = F.kind == Formula::And ? std::min(t, truth(k)) : std::max(t, truth(k));
  return t;
}

int Evaluator::feasible(const Ival* box) {
  int t = 2;
  if (m_.constraints.empty()) return t;
  eval(all_atoms, box, Mode::Truth);
  for (int c : m_.constraints) t = std::min(t, truth(c));
  return t;
}

bool Evaluator::eval_ad(const std::vector<int>& prog, const Ival* box, uint64_t dirs) {
  dirs_ = dirs;
  if (!eval(prog, box, Mode::Proof)) return false;
  charge(prog.size());
  for (int id : prog)
    if (!derive(id)) return false;
  return true;
}

// Derivatives of node id w.r.t. the requested variables it mentions. A unary node is
// g(a) with g' computed once into g_; non-differentiable points make the proof fail.
bool Evaluator::derive(int id) {
  const Node& n = m_.nodes[id];
  const uint64_t need = n.dep & dirs_;
  if (!need) return true;
  const int nv = this->nv();
  Ival* D = &der_[size_t(id) * nv];
  if (n.op == Op::Var) {
    set_si(D[n.k], 1);
    return true;
  }
  const Ival* A = &der_[size_t(n.a) * nv];
  const Ival* B = n.b >= 0 ? &der_[size_t(n.b) * nv] : nullptr;
  const Ival& a = val_[n.a];
  const Ival& b = n.b >= 0 ? val_[n.b] : a;
  const Ival& r = val_[id];
  const bool unary = n.b < 0;
  switch (n.op) {
    case Op::Neg: set_si(g_, -1); break;
    case Op::Sqr: mul_d(g_, a, 2); break;
    case Op::Pow:
      power(g_, a, n.k - 1);
      mul_d(g_, g_, n.k);
      break;
    case Op::Sqrt:  // not differentiable at 0
      if (r.has_zero()) return false;
      mul_d(g_, r, 2);
      inv(g_, g_);
      break;
    case Op::Exp: g_ = r; break;
    case Op::Log: inv(g_, a); break;
    case Op::Sin: trig(true, n.a, a, g_); break;
    case Op::Cos:
      trig(false, n.a, a, g_);
      neg(g_, g_);
      break;
    case Op::Tan:
      sqr(g_, r);
      add_d(g_, g_, 1);
      break;
    case Op::Abs:
      if (!a.sign()) return false;
      set_si(g_, a.sign());
      break;
    case Op::Asin:
    case Op::Acos:
      sqr(g_, a);
      si_sub(g_, 1, g_);
      if (g_.end_sign(Lo) <= 0) return false;
      sqrt(g_, g_);
      inv(g_, g_);
      if (n.op == Op::Acos) neg(g_, g_);
      break;
    case Op::Atan:
      sqr(g_, a);
      add_d(g_, g_, 1);
      inv(g_, g_);
      break;
    default: break;  // binary: below; constants and variables: above
  }
  for (int v = 0; v < nv; ++v) {
    if (!(need >> v & 1)) continue;
    Ival& d = D[v];
    if (unary) {
      mul(d, g_, A[v]);
    } else if (n.op == Op::Add) {
      add(d, A[v], B[v]);
    } else if (n.op == Op::Sub) {
      sub(d, A[v], B[v]);
    } else if (n.op == Op::Mul) {
      mul(t1_, A[v], b);
      mul(t2_, a, B[v]);
      add(d, t1_, t2_);
    } else if (n.op == Op::Div) {  // (a' - r b') / b
      mul(t1_, r, B[v]);
      sub(t1_, A[v], t1_);
      div(d, t1_, b);
    } else {  // min/max: differentiable only where one argument is certainly smaller
      const bool a_less = less(a, Hi, b, Lo);
      const bool b_less = less(b, Hi, a, Lo);
      if (!a_less && !b_less) return false;
      d = (a_less == (n.op == Op::Min)) ? A[v] : B[v];
    }
    if (!d.bounded()) return false;
  }
  return true;
}

bool Evaluator::hc4(int eq, Ival* box) {
  const std::vector<int>& prog = eq_prog[eq];
  if (!eval(prog, box, Mode::Refute)) return false;
  for (int id : prog) stamp_[id] = 0;  // the backward pass narrows the values
  set_si(t1_, 0);
  if (!val_[m_.eqs[eq]].meet(t1_)) return false;
  charge(prog.size());
  for (auto it = prog.rbegin(); it != prog.rend(); ++it)
    if (!backward(*it, box)) return false;
  return true;
}

// x ∩= t, ignoring a NaN t (no information); false when x becomes empty.
static bool cut(Ival& x, const Ival& t) { return t.nan() ? true : x.meet(t); }

bool Evaluator::hull_both(Ival& a, const Ival& s) {
  if (s.nan()) return true;  // no information
  intersect(t2_, a, s);
  neg(t3_, s);
  intersect(t3_, a, t3_);
  if (t2_.empty() && t3_.empty()) return false;
  if (t2_.empty()) a = t3_;
  if (t3_.empty()) a = t2_;
  if (!t2_.empty() && !t3_.empty()) hull(a, t2_, t3_);
  return true;
}

// r ∩= [0, +inf]; false when r becomes empty.
bool Evaluator::meet_nonnegative(Ival& r) {
  t1_.set(0, INFINITY);
  return r.meet(t1_);
}

// r = a²: r ∩= [0, +inf], then a ∩= ±sqrt(r).
bool Evaluator::project_square(Ival& r, Ival& a) {
  if (!meet_nonnegative(r)) return false;
  sqrt(t1_, r);
  return hull_both(a, t1_);
}

bool Evaluator::backward(int id, Ival* box) {
  const Node& n = m_.nodes[id];
  if (!n.dep) return true;
  Ival& r = val_[id];
  Ival* a = n.a >= 0 ? &val_[n.a] : nullptr;
  Ival* b = n.b >= 0 ? &val_[n.b] : nullptr;
  switch (n.op) {
    case Op::Var: return box[n.k].meet(r);
    case Op::Add:  // a ∈ r − b, then b ∈ r − a
      sub(t1_, r, *b);
      if (!cut(*a, t1_)) return false;
      sub(t1_, r, *a);
      return cut(*b, t1_);
    case Op::Sub:  // a ∈ r + b, then b ∈ a − r
      add(t1_, r, *b);
      if (!cut(*a, t1_)) return false;
      sub(t1_, *a, r);
      return cut(*b, t1_);
    case Op::Neg:
      neg(t1_, r);
      return cut(*a, t1_);
    case Op::Mul:
      if (n.a == n.b) return project_square(r, *a);
      if (!b->has_zero()) {
        div(t1_, r, *b);
        if (!cut(*a, t1_)) return false;
      }
      if (!a->has_zero()) {
        div(t1_, r, *a);
        if (!cut(*b, t1_)) return false;
      }
      return true;
    case Op::Div:  // a = r·b and b = a/r wherever a/b is defined
      if (r.bounded()) {
        mul(t1_, r, *b);
        if (!cut(*a, t1_)) return false;
      }
      if (!r.has_zero()) {
        div(t1_, *a, r);
        if (!cut(*b, t1_)) return false;
      }
      return true;
    case Op::Min:  // min(a, b) >= lo(r) forces a, b >= lo(r); max(a, b) <= hi(r) likewise
      t1_ = r;
      t1_.set_end(Hi, INFINITY);
      return cut(*a, t1_) && cut(*b, t1_);
    case Op::Max:
      t1_ = r;
      t1_.set_end(Lo, -INFINITY);
      return cut(*a, t1_) && cut(*b, t1_);
    case Op::Sqr: return project_square(r, *a);
    case Op::Pow: {
      if (n.k < 0) return true;  // no projection: weak but sound
      bool even = n.k % 2 == 0;
      if (even && !meet_nonnegative(r)) return false;
      rootn_ui(t1_, r, (unsigned long)n.k);
      return even ? hull_both(*a, t1_) : cut(*a, t1_);
    }
    case Op::Sqrt:  // a ∈ (r ∩ [0, +inf])²
      if (!meet_nonnegative(r)) return false;
      sqr(t1_, r);
      return cut(*a, t1_);
    case Op::Exp:  // a ∈ log(r ∩ [0, +inf])
      if (!meet_nonnegative(r)) return false;
      apply_fn(Fn::Log, t1_, r);
      return cut(*a, t1_);
    case Op::Log:
      apply_fn(Fn::Exp, t1_, r);
      return cut(*a, t1_);
    case Op::Abs: return meet_nonnegative(r) && hull_both(*a, r);
    case Op::Asin:  // a = sin(asin a) ∈ sin(r)
      apply_fn(Fn::Sin, t1_, r);
      return cut(*a, t1_);
    case Op::Acos:
      apply_fn(Fn::Cos, t1_, r);
      return cut(*a, t1_);
    case Op::Atan:  // no information where tan(r) is unbounded
      apply_fn(Fn::Tan, t1_, r);
      return !t1_.bounded() || cut(*a, t1_);
    case Op::Sin:
    case Op::Cos:  // r ∩ [−1, 1], then the preimage of r in a: one branch, or all of them
      t1_.set(-1, 1);
      if (!r.meet(t1_)) return false;
      trig(n.op == Op::Cos, n.a, *a, t4_);
      // Nothing to remove when the image is already inside r; huge arguments are left alone.
      if (is_inside(t4_, r)) return true;
      if (!(std::fabs(a->lo()) < 1e6 && std::fabs(a->hi()) < 1e6)) return true;
      if (a->hi() - a->lo() < 3 && monotone_projection(n.op, r, *a, t4_))
        return !less(*a, Hi, *a, Lo);
      return project_general(n.op, r, *a);
    case Op::Tan: case Op::Const: case Op::Pi:
      return true;
  }
  return true;
}

// out := enclosure of s·asin(y) + cπ (sin) or s·acos(y) + cπ (cos), y an end of r: by MPFI
// on the point y, or by Arb (eval_speed.cpp).
void Evaluator::branch_inverse(Op op, const Ival& r, End e, int s, double c, Ival& out) {
  if (speed) {
    arb_inverse(op, r, e, out);
  } else {
    Ival y;  // not a member's scratch: the callers hold some of them
    point(y, r, e);
    apply_fn(op == Op::Sin ? Fn::Asin : Fn::Acos, out, y);
  }
  if (s < 0) neg(out, out);
  mul_d(t3_, pi_, c);
  add(out, out, t3_);
}

// When a provably lies in one monotone branch [(j+off)π, (j+1+off)π] of sin (off = 1/2)
// or cos (off = 0), the preimage of r in a is an interval whose ends are branch inverses
// of r's ends, needed only where r is narrower than the image fa of a. The branch
// starts at an extremum of value (−1)^j, so the function decreases on it iff j is even.
// Returns false (nothing done) when a is not provably inside one branch.
bool Evaluator::monotone_projection(Op op, const Ival& r, Ival& a, const Ival& fa) {
  const double PI = 3.141592653589793;
  const double off = op == Op::Sin ? 0.5 : 0.0;
  double j = std::floor(0.5 * (a.lo() + a.hi()) / PI - off);
  mul_d(t3_, pi_, j + off);
  if (less(a, Lo, t3_, Hi)) return false;
  mul_d(t3_, pi_, j + 1 + off);
  if (less(t3_, Lo, a, Hi)) return false;
  bool dec = std::fmod(std::fabs(j), 2.0) == 0;
  // sin: −asin on decreasing branches; cos: −acos on increasing ones.
  int s = (op == Op::Sin) == dec ? -1 : 1;
  double c = (op == Op::Cos && dec) ? j : j + 1;
  if (dec ? less(r, Hi, fa, Hi) : less(fa, Lo, r, Lo)) {
    branch_inverse(op, r, dec ? Hi : Lo, s, c, t2_);
    if (less(a, Lo, t2_, Lo)) copy_end(a, Lo, t2_, Lo);
  }
  if (dec ? less(fa, Lo, r, Lo) : less(r, Hi, fa, Hi)) {
    branch_inverse(op, r, dec ? Lo : Hi, s, c, t2_);
    if (less(t2_, Hi, a, Hi)) copy_end(a, Hi, t2_, Hi);
  }
  return true;
}

// Otherwise a ∩= ∪k (s + 2kπ) ∪ (π − s + 2kπ) with s = asin(r) ⊆ [−π/2, π/2]
// (sin), or ∪k (±s + 2kπ) with s = acos(r) ⊆ [0, π] (cos): every preimage of r. The
// pieces are interval enclosures, and the k range (margin 2) covers every piece that can
// meet a (|a| < 1e6).
bool Evaluator::project_general(Op op, const Ival& r, Ival& a) {
  if (op == Op::Sin) apply_fn(Fn::Asin, t1_, r);
  else apply_fn(Fn::Acos, t1_, r);
  const double P = 6.283185307179586;
  const double kmin = std::floor(a.lo() / P) - 2;
  const double kmax = std::floor(a.hi() / P) + 2;
  if (kmax - kmin > 10) return true;  // spans many periods: nothing to gain
  bool any = false;
  for (double k = kmin; k <= kmax; ++k)
    for (int branch = 0; branch < 2; ++branch) {
      if (branch == 0) t2_ = t1_;
      else if (op == Op::Sin) sub(t2_, pi_, t1_);
      else neg(t2_, t1_);
      // A piece that clearly misses a (in double, with a margin) is skipped.
      if (t2_.hi() + k * P < a.lo() - 1e-6 || t2_.lo() + k * P > a.hi() + 1e-6) continue;
      mul_d(t3_, two_pi, long(k));
      add(t2_, t2_, t3_);
      intersect(t2_, t2_, a);
      if (t2_.empty()) continue;
      if (any) hull(g_, g_, t2_);
      else g_ = t2_;
      any = true;
    }
  if (any) a = g_;
  return any;
}

}  // namespace cc
