// model.h — the checker's own representation of a robot model: an expression DAG whose
// children always have smaller ids than their parents (so increasing id order is a forward
// evaluation order), the variables in declaration order, the equations (lhs - rhs) and the
// user factors, and the constraint formulas (paper 5.4). The parser is purely syntactic:
// literals are kept as decimal strings and turned into enclosing MPFI intervals by the
// evaluator (mpfi_set_str), never via strtod.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace cc {

enum class Op : uint8_t {
  Const, Pi, Var, Add, Sub, Mul, Div, Min, Max,
  Neg, Sqr, Sqrt, Sin, Cos, Tan, Exp, Log, Abs, Asin, Acos, Atan, Pow
};

struct Node {
  Op op;
  int a = -1, b = -1;
  int k = 0;         // Var: variable index; Const: literal index; Pow: exponent
  uint64_t dep = 0;  // bit v: the node mentions variable v (after expanding names)
};

struct Var {
  std::string name;
  bool pose = false, periodic = false;
  int lo = -1, hi = -1;  // nodes of the declared bounds (constant expressions)
};

// A node of a constraint formula: an atom g >= 0 (g > 0 if strict) or the and/or of kids.
struct Formula {
  enum Kind : uint8_t { Atom, And, Or } kind = Atom;
  bool strict = false;
  int expr = -1;  // Atom: node of g (E1 - E2, or E2 - E1 for <= and <)
  std::vector<int> kids;
};

struct Model {
  std::string name;
  std::vector<Node> nodes;
  std::vector<std::string> literals;
  std::vector<Var> vars;
  std::vector<int> pose, command;  // variable indices, declaration order
  std::vector<int> eqs, factors;   // root nodes
  std::vector<Formula> formulas;
  std::vector<int> constraints, atoms;  // root formula of each constraint; node g of each atom
  int n() const { return int(eqs.size()); }
};

struct ModelError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Parses the model language; throws ModelError("LINE:COL: message").
Model parse_model(const std::string& text);

// True when the declared domain of v is exactly one period: both bounds are a·π + b with
// exact rationals a, b (decimal literals, pi, +, -, and * or / by a rational) and
// hi − lo = 2π exactly. An interval test cannot decide this: a decimal bound close enough
// to π passes it at any fixed precision, and leaves a gap at the seam.
bool exactly_one_period(const Model& m, const Var& v);

}  // namespace cc
