#include "model/constant_values.h"

#include <numeric>
#include <stdexcept>
#include <vector>

namespace aspects {

int ConstantValues::copy(int root) {
  std::vector<int> stack{root};
  while (!stack.empty()) {
    const int id = stack.back();
    if (copy_of_.count(id)) {
      stack.pop_back();
      continue;
    }
    const Node& n = dag_.node(id);
    bool children_copied = true;
    for (int c : {n.a, n.b})
      if (c >= 0 && !copy_of_.count(c)) {
        stack.push_back(c);
        children_copied = false;
      }
    if (!children_copied) continue;
    stack.pop_back();
    // Through the public builders, which simplify (x + 0, x * 1, ...) as they did when the
    // node was made: its children are copies of the same constants (equal enclosures share
    // a node in both DAGs), so the copy is the same operation on the same values.
    const int a = n.a >= 0 ? copy_of_.at(n.a) : -1, b = n.b >= 0 ? copy_of_.at(n.b) : -1;
    int c;
    if (n.op == Op::Const)
      c = copies_.constant(dag_.constant_value(id));
    else if (n.op == Op::Var)
      throw std::logic_error("ConstantValues: node depends on a variable");
    else if (n.op == Op::Pow)
      c = copies_.pow(a, n.k);
    else if (is_binary(n.op))
      c = copies_.binary(n.op, a, b, /*keep_operands=*/true);
    else
      c = copies_.unary(n.op, a);
    copy_of_.emplace(id, c);
  }
  return copy_of_.at(root);
}

const Interval& ConstantValues::value(int node) {
  const int c = copy(node);
  if (copies_.size() > evaluated_) {
    // The new nodes only, in increasing ids (children first); the older ones keep their
    // values: a constant's value does not depend on the box.
    std::vector<int> program(size_t(copies_.size() - evaluated_));
    std::iota(program.begin(), program.end(), evaluated_);
    eval_.forward(program, Box{});
    evaluated_ = copies_.size();
  }
  return eval_.value(c);
}

}  // namespace aspects
