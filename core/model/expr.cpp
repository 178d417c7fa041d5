#include "model/expr.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace aspects {

const char* op_name(Op op) {
  switch (op) {
    case Op::Const: return "const";
    case Op::Var: return "var";
    case Op::Add: return "+";
    case Op::Sub: return "-";
    case Op::Mul: return "*";
    case Op::Div: return "/";
    case Op::Min: return "min";
    case Op::Max: return "max";
    case Op::Neg: return "-";
    case Op::Sqr: return "sqr";
    case Op::Sqrt: return "sqrt";
    case Op::Sin: return "sin";
    case Op::Cos: return "cos";
    case Op::Tan: return "tan";
    case Op::Exp: return "exp";
    case Op::Log: return "log";
    case Op::Abs: return "abs";
    case Op::Asin: return "asin";
    case Op::Acos: return "acos";
    case Op::Atan: return "atan";
    case Op::Pow: return "^";
    case Op::Sign: return "sign";
    case Op::Step: return "step";
  }
  return "?";
}

bool is_binary(Op op) {
  return op == Op::Add || op == Op::Sub || op == Op::Mul || op == Op::Div || op == Op::Min ||
         op == Op::Max || op == Op::Step;
}

Dag::Dag() {
  zero_ = constant(0.0);
  one_ = constant(1.0);
}

int Dag::add_node(Node n) {
  auto key = std::make_tuple(int(n.op), n.a, n.b, n.k);
  auto it = index_.find(key);
  if (it != index_.end()) return it->second;
  int id = int(nodes_.size());
  nodes_.push_back(n);
  std::vector<int> deps;
  if (n.op == Op::Var) deps.push_back(n.k);
  for (int c : {n.a, n.b}) {
    if (c < 0) continue;
    std::vector<int> merged;
    std::set_union(deps.begin(), deps.end(), var_deps_[c].begin(), var_deps_[c].end(),
                   std::back_inserter(merged));
    deps.swap(merged);
  }
  depends_.push_back(!deps.empty());
  depth_.push_back(1 + std::max(n.a >= 0 ? depth_[n.a] : 0, n.b >= 0 ? depth_[n.b] : 0));
  var_deps_.push_back(std::move(deps));
  index_.emplace(key, id);
  return id;
}

namespace {

// Appends the exact value of x as bytes: its kind (with the sign), and for a regular number
// its exponent and significand limbs, the low zero limbs left out so that equal values at
// different precisions have one key. Equal keys are equal values. (It was the text "%Ra"
// of each end: a third of the parse of a long expression went there.)
void append_exact(std::string& key, mpfr_srcptr x) {
  auto raw = [&key](const void* p, size_t bytes) {
    key.append(static_cast<const char*>(p), bytes);
  };
  const mpfr_ptr y = const_cast<mpfr_ptr>(x);  // the custom interface only reads here
  const int kind = mpfr_custom_get_kind(y);
  raw(&kind, sizeof kind);
  if (kind != MPFR_REGULAR_KIND && kind != -MPFR_REGULAR_KIND) return;
  const mpfr_exp_t exp = mpfr_custom_get_exp(y);
  raw(&exp, sizeof exp);
  // Limbs from the least significant (index 0) to the most; unused low bits are zero.
  const mp_limb_t* limbs = static_cast<const mp_limb_t*>(mpfr_custom_get_significand(y));
  size_t n = mpfr_custom_get_size(mpfr_get_prec(x)) / sizeof(mp_limb_t), low = 0;
  while (low < n && limbs[low] == 0) ++low;
  raw(limbs + low, (n - low) * sizeof(mp_limb_t));
}

}  // namespace

int Dag::constant(const Interval& v) {
  // Identical enclosures share a node; the key is the exact endpoints, at full length (a
  // truncated key could merge two different constants).
  std::string key;
  append_exact(key, &v.get()->left);
  append_exact(key, &v.get()->right);
  auto it = const_index_.find(key);
  if (it != const_index_.end()) return it->second;
  consts_.push_back(v);
  Node n{Op::Const, -1, -1, int(consts_.size() - 1)};
  int id = add_node(n);
  const_index_.emplace(key, id);
  return id;
}

int Dag::constant(double v) { return constant(Interval(v)); }

int Dag::var(int index) { return add_node(Node{Op::Var, -1, -1, index}); }

int Dag::unary(Op op, int a) {
  if (op == Op::Neg && a == zero_) return zero_;
  return add_node(Node{op, a, -1, 0});
}

int Dag::binary(Op op, int a, int b, bool keep_operands) {
  auto droppable = [&](int x) { return !keep_operands || is_constant(x); };
  switch (op) {
    case Op::Add:
      if (a == zero_) return b;
      if (b == zero_) return a;
      if (a > b) std::swap(a, b);
      break;
    case Op::Sub:
      if (b == zero_) return a;
      if (a == zero_) return unary(Op::Neg, b);
      break;
    case Op::Mul:
      if ((a == zero_ && droppable(b)) || (b == zero_ && droppable(a))) return zero_;
      if (a == one_) return b;
      if (b == one_) return a;
      if (a > b) std::swap(a, b);
      break;
    case Op::Div:
      if (a == zero_ && droppable(b)) return zero_;
      if (b == one_) return a;
      break;
    default:
      break;
  }
  return add_node(Node{op, a, b, 0});
}

int Dag::pow(int a, int k) {
  if (k == 0) return one_;
  if (k == 1) return a;
  if (k == 2) return unary(Op::Sqr, a);
  return add_node(Node{Op::Pow, a, -1, k});
}

bool Dag::depends_on(int node, int v) const {
  return std::binary_search(var_deps_[node].begin(), var_deps_[node].end(), v);
}

int Dag::derivative(int node, int var) {
  if (!depends_on(node, var)) return zero_;
  auto key = std::make_pair(node, var);
  auto it = deriv_memo_.find(key);
  if (it != deriv_memo_.end()) return it->second;
  int d = derive(node, var);
  deriv_memo_.emplace(key, d);
  return d;
}

int Dag::derive(int id, int v) {
  const Node n = nodes_[id];  // copy: nodes_ grows below
  auto D = [&](int c) { return derivative(c, v); };
  auto mul = [&](int x, int y) { return binary(Op::Mul, x, y); };
  auto add = [&](int x, int y) { return binary(Op::Add, x, y); };
  auto sub = [&](int x, int y) { return binary(Op::Sub, x, y); };
  auto div = [&](int x, int y) { return binary(Op::Div, x, y); };
  switch (n.op) {
    case Op::Const: return zero_;
    case Op::Var: return n.k == v ? one_ : zero_;
    case Op::Add: return add(D(n.a), D(n.b));
    case Op::Sub: return sub(D(n.a), D(n.b));
    case Op::Mul: return add(mul(D(n.a), n.b), mul(n.a, D(n.b)));
    case Op::Div:
      return sub(div(D(n.a), n.b), div(mul(n.a, D(n.b)), unary(Op::Sqr, n.b)));
    case Op::Min: {
      int s = binary(Op::Step, n.a, n.b);
      return add(mul(s, D(n.a)), mul(sub(one_, s), D(n.b)));
    }
    case Op::Max: {
      int s = binary(Op::Step, n.b, n.a);
      return add(mul(s, D(n.a)), mul(sub(one_, s), D(n.b)));
    }
    case Op::Neg: return unary(Op::Neg, D(n.a));
    case Op::Sqr: return mul(mul(constant(2.0), n.a), D(n.a));
    case Op::Sqrt: return div(D(n.a), mul(constant(2.0), id));
    case Op::Sin: return mul(unary(Op::Cos, n.a), D(n.a));
    case Op::Cos: return unary(Op::Neg, mul(unary(Op::Sin, n.a), D(n.a)));
    case Op::Tan: return mul(add(one_, unary(Op::Sqr, id)), D(n.a));
    case Op::Exp: return mul(id, D(n.a));
    case Op::Log: return div(D(n.a), n.a);
    case Op::Abs: return mul(unary(Op::Sign, n.a), D(n.a));
    case Op::Asin: return div(D(n.a), unary(Op::Sqrt, sub(one_, unary(Op::Sqr, n.a))));
    case Op::Acos:
      return unary(Op::Neg, div(D(n.a), unary(Op::Sqrt, sub(one_, unary(Op::Sqr, n.a)))));
    case Op::Atan: return div(D(n.a), add(one_, unary(Op::Sqr, n.a)));
    case Op::Pow: return mul(mul(constant(double(n.k)), pow(n.a, n.k - 1)), D(n.a));
    case Op::Sign:
    case Op::Step:
      return zero_;  // piecewise constant; their jumps are where the parent is not smooth
  }
  throw std::logic_error("derive: unknown op");
}

std::vector<int> Dag::closure(const std::vector<int>& roots) const {
  std::vector<char> need(nodes_.size(), 0);
  for (int r : roots) need[r] = 1;
  for (int id = int(nodes_.size()) - 1; id >= 0; --id) {
    if (!need[id]) continue;
    if (nodes_[id].a >= 0) need[nodes_[id].a] = 1;
    if (nodes_[id].b >= 0) need[nodes_[id].b] = 1;
  }
  std::vector<int> out;
  for (int id = 0; id < int(nodes_.size()); ++id)
    if (need[id]) out.push_back(id);
  return out;
}

namespace {
int precedence(const Node& n) {
  switch (n.op) {
    case Op::Add:
    case Op::Sub: return 1;
    case Op::Mul:
    case Op::Div: return 2;
    case Op::Neg: return 3;
    case Op::Pow:
    case Op::Sqr: return 4;
    default: return 5;
  }
}
}  // namespace

std::string Dag::to_string(int id, const std::vector<std::string>& names) const {
  std::string out;
  write(id, names, out);
  if (out.size() > kMaxTextLength) {
    out.resize(kMaxTextLength);
    out += " ...";
  }
  return out;
}

// Appends node `id` to `out`, and stops expanding once out is longer than the limit: a DAG
// with shared nodes (a_i = a_{i-1} + a_{i-1}) has a text exponentially longer than itself.
void Dag::write(int id, const std::vector<std::string>& names, std::string& out) const {
  if (out.size() > kMaxTextLength) return;
  const Node& n = nodes_[id];
  auto sub = [&](int c, int min_prec) {
    const bool parens = precedence(nodes_[c]) < min_prec;
    if (parens) out += '(';
    write(c, names, out);
    if (parens) out += ')';
  };
  auto binary = [&](int left_prec, const char* op, int right_prec) {
    sub(n.a, left_prec);
    out += op;
    sub(n.b, right_prec);
  };
  switch (n.op) {
    case Op::Const: {
      const Interval& c = consts_[n.k];
      double lo = c.lo_down(), hi = c.hi_up();
      char buf[96];
      if (lo == hi)
        std::snprintf(buf, sizeof buf, "%.17g", lo);
      else
        std::snprintf(buf, sizeof buf, "[%.17g, %.17g]", lo, hi);
      out += buf;
      return;
    }
    case Op::Var: out += names.at(n.k); return;
    case Op::Add: binary(1, " + ", 1); return;
    case Op::Sub: binary(1, " - ", 2); return;
    case Op::Mul: binary(2, "*", 3); return;
    case Op::Div: binary(2, "/", 3); return;
    case Op::Neg:
      out += '-';
      sub(n.a, 3);
      return;
    case Op::Sqr:
      sub(n.a, 5);
      out += "^2";
      return;
    case Op::Pow:
      sub(n.a, 5);
      out += "^" + std::to_string(n.k);
      return;
    case Op::Min:
    case Op::Max:
    case Op::Step:
      out += std::string(op_name(n.op)) + "(";
      write(n.a, names, out);
      out += ", ";
      write(n.b, names, out);
      out += ')';
      return;
    default:
      out += std::string(op_name(n.op)) + "(";
      write(n.a, names, out);
      out += ')';
      return;
  }
}

}  // namespace aspects
