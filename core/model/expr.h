// Expression DAG shared by every constraint of a model. Nodes are hash-consed, so a
// sub-expression written twice (or produced twice by differentiation) is one node and
// is evaluated once. Children always have smaller ids than their parents: evaluating
// nodes in increasing id order is a valid forward order, decreasing id a backward one.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "numerics/interval.h"

namespace aspects {

enum class Op : uint8_t {
  Const, Var,
  Add, Sub, Mul, Div, Min, Max,           // binary
  Neg, Sqr, Sqrt, Sin, Cos, Tan, Exp, Log, Abs, Asin, Acos, Atan,  // unary
  Pow,                                     // integer exponent in Node::k
  Sign,                                    // internal: derivative of abs
  Step,                                    // internal: 1 if a < b, 0 if a > b, [0,1] if unsure
};

const char* op_name(Op op);
bool is_binary(Op op);

struct Node {
  Op op;
  int a = -1, b = -1;  // children
  int k = 0;           // Var: variable index; Const: constant index; Pow: exponent
};

class Dag {
 public:
  Dag();
  int size() const { return int(nodes_.size()); }
  const Node& node(int id) const { return nodes_[id]; }
  const Interval& constant_value(int id) const { return consts_[nodes_[id].k]; }

  int constant(const Interval& v);
  int constant(double v);  // exact double
  int var(int index);
  int unary(Op op, int a);
  // Simplifies x+0, x*1, x*0, 0/x... With keep_operands, never drops an operand that
  // depends on a variable (x*0 stays): the model's own expressions must keep every
  // sub-expression, since a point where one is undefined is not a solution.
  int binary(Op op, int a, int b, bool keep_operands = false);
  int pow(int a, int k);
  int zero() const { return zero_; }
  int one() const { return one_; }

  // d node / d var, as a node of this DAG (memoised, simplified for 0 and 1).
  int derivative(int node, int var);
  // True when node does not depend on any variable.
  bool is_constant(int node) const { return !depends_[node]; }
  // Length of the longest path from the node down to a leaf (recursions are bounded
  // by it: the parser caps it).
  int depth(int node) const { return depth_[node]; }
  // Bitmask-free dependency query: does node depend on variable v?
  bool depends_on(int node, int v) const;
  // Ids of the nodes a set of roots needs, in increasing (forward) order.
  std::vector<int> closure(const std::vector<int>& roots) const;
  // Human-readable form, fully parenthesised where needed; cut after kMaxTextLength
  // characters (then ending in " ...").
  std::string to_string(int node, const std::vector<std::string>& var_names) const;
  static constexpr size_t kMaxTextLength = size_t(1) << 16;

 private:
  int add_node(Node n);
  void write(int node, const std::vector<std::string>& var_names, std::string& out) const;
  int derive(int node, int var);

  std::vector<Node> nodes_;
  std::vector<Interval> consts_;
  std::vector<bool> depends_;
  std::vector<int> depth_;
  std::map<std::tuple<int, int, int, int>, int> index_;
  std::map<std::string, int> const_index_;  // both ends' exact bytes -> node
  std::map<std::pair<int, int>, int> deriv_memo_;
  std::vector<std::vector<int>> var_deps_;  // sorted variable list per node
  int zero_ = -1, one_ = -1;
};

}  // namespace aspects
