// derivative.cpp — trusted core: the Jacobian of f as nodes of the model's DAG, by the
// classical rules of differentiation, so that the evaluator's forward-mode AD (eval_ad) on
// those nodes encloses the second derivatives of f: the gradients of the determinant
// factors that a count certificate's star test needs (count_connected.cpp). min, max and abs
// have no rule (where they matter, the Jacobian entry is −1 and the star test fails), and
// every rule's expression is undefined exactly where the AD of eval.cpp fails (a square root
// at 0, a pole), so an enclosure is proved only where the derivative exists.
#include <map>
#include <tuple>

#include "checker.h"

namespace cc {

namespace {

constexpr int kZero = -2;  // a derivative that is structurally 0 (no node)

class Differentiator {
 public:
  explicit Differentiator(Model& m) : m_(m) {
    for (size_t id = 0; id < m_.nodes.size(); ++id) {
      const Node& n = m_.nodes[id];
      memo_.emplace(std::make_tuple(n.op, n.a, n.b, n.k), int(id));
    }
  }

  // d node / d var v: a node id, kZero, or −1 (no rule).
  int d(int id, int v) {
    const Node n = m_.nodes[id];
    if (!(n.dep >> v & 1)) return kZero;
    auto hit = done_.find({id, v});
    if (hit != done_.end()) return hit->second;
    const int r = rule(id, n, v);
    done_[{id, v}] = r;
    return r;
  }

  int literal(const std::string& text) {
    auto l = literals_.find(text);
    int k;
    if (l != literals_.end()) {
      k = l->second;
    } else {
      k = int(m_.literals.size());
      m_.literals.push_back(text);
      literals_[text] = k;
    }
    return node(Op::Const, -1, -1, k);
  }

 private:
  Model& m_;
  std::map<std::tuple<Op, int, int, int>, int> memo_;
  std::map<std::pair<int, int>, int> done_;
  std::map<std::string, int> literals_;

  int node(Op op, int a = -1, int b = -1, int k = 0) {
    auto memo = memo_.emplace(std::make_tuple(op, a, b, k), int(m_.nodes.size()));
    if (!memo.second) return memo.first->second;
    Node n{op, a, b, k, 0};
    if (a >= 0) n.dep |= m_.nodes[a].dep;
    if (b >= 0) n.dep |= m_.nodes[b].dep;
    m_.nodes.push_back(n);
    return int(m_.nodes.size()) - 1;
  }
  // Sums and products that skip the structural zeros.
  int plus(int a, int b) { return a == kZero ? b : b == kZero ? a : node(Op::Add, a, b); }
  int minus(int a, int b) {
    if (b == kZero) return a;
    return a == kZero ? node(Op::Neg, b) : node(Op::Sub, a, b);
  }
  int times(int a, int b) { return a == kZero || b == kZero ? kZero : node(Op::Mul, a, b); }
  int over(int a, int b) { return a == kZero ? kZero : node(Op::Div, a, b); }

  int rule(int id, const Node& n, int v) {
    if (n.op == Op::Var) return literal("1");
    const int da = n.a >= 0 ? d(n.a, v) : kZero;
    const int db = n.b >= 0 ? d(n.b, v) : kZero;
    if (da == -1 || db == -1) return -1;
    const int a = n.a;
    switch (n.op) {
      case Op::Add: return plus(da, db);
      case Op::Sub: return minus(da, db);
      case Op::Mul: return plus(times(da, n.b), times(a, db));
      case Op::Div: return over(minus(da, times(id, db)), n.b);  // (a' − (a/b)·b') / b
      case Op::Neg: return da == kZero ? kZero : node(Op::Neg, da);
      case Op::Sqr: return times(times(literal("2"), a), da);
      case Op::Pow: {  // k·a^(k−1)·a'
        const int k = n.k;
        const int p = k - 1 == 1 ? a : k - 1 == 2 ? node(Op::Sqr, a) : node(Op::Pow, a, -1, k - 1);
        const int c = k > 0 ? literal(std::to_string(k)) : node(Op::Neg, literal(std::to_string(-k)));
        return times(times(c, p), da);
      }
      case Op::Sqrt: return over(da, times(literal("2"), id));
      case Op::Exp: return times(id, da);
      case Op::Log: return over(da, a);
      case Op::Sin: return times(node(Op::Cos, a), da);
      case Op::Cos: return da == kZero ? kZero : node(Op::Neg, times(node(Op::Sin, a), da));
      case Op::Tan: return times(node(Op::Add, literal("1"), node(Op::Sqr, id)), da);
      case Op::Asin:
      case Op::Acos: {
        const int r = over(da, node(Op::Sqrt, node(Op::Sub, literal("1"), node(Op::Sqr, a))));
        return n.op == Op::Asin || r == kZero ? r : node(Op::Neg, r);
      }
      case Op::Atan: return over(da, node(Op::Add, literal("1"), node(Op::Sqr, a)));
      default: return -1;  // min, max, abs (constants and variables are handled above)
    }
  }
};

}  // namespace

// Appends to m the nodes of ∂f_r/∂x_v (row r, variable v: out[r][v], −1 where no rule).
std::vector<std::vector<int>> jacobian_nodes(Model& m) {
  Differentiator diff(m);
  const int zero = diff.literal("0");
  std::vector<std::vector<int>> out(m.eqs.size(), std::vector<int>(m.vars.size()));
  for (size_t r = 0; r < m.eqs.size(); ++r)
    for (size_t v = 0; v < m.vars.size(); ++v) {
      const int e = diff.d(m.eqs[r], int(v));
      out[r][v] = e == kZero ? zero : e;
    }
  return out;
}

}  // namespace cc
