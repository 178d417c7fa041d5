#!/usr/bin/env python3
"""Writes large robot models, one per shape the parser might handle in more than linear
time, each about SIZE bytes: bench/parse_scaling.sh times `aspects info` on them.

Usage: parse_models.py OUT_DIR SIZE_BYTES

Shapes (each a valid model up to its size, or refused by a rule the parser applies):
  constants    many `constant` statements, and a domain bound using the last one
  periodic     the same constants, then 16 variables, 8 of them periodic
  expression   one equation whose expression is a balanced sum of products (depth ~20)
  lets         many `let` statements each used once by an equation's sum
  variables    pose declarations past the limit of 16 variables (refused at the 17th)
  constraint   one constraint: a conjunction of parenthesised comparisons of long sums
  parens       a constraint whose comparison is nested in many parentheses of sums
"""
import os
import sys


def constants(size):
    lines = ["robot Constants"]
    i = 0
    total = 0
    while total < size:
        line = f"constant c{i} = {i}.25 * 2 + 1"
        lines.append(line)
        total += len(line) + 1
        i += 1
    lines += [f"pose x in [-c{i - 1}, c{i - 1}]", "command q in [-1, 1]", "equation x - q = 0"]
    return lines


def balanced(leaves, lo, hi, depth=0):
    if hi - lo == 1:
        return leaves[lo]
    mid = (lo + hi) // 2
    op = " + " if depth % 2 == 0 else " * "
    return "(" + balanced(leaves, lo, mid, depth + 1) + op + balanced(leaves, mid, hi, depth + 1) + ")"


def periodic(size):
    lines = constants(size)[:-3]
    lines[0] = "robot Periodic"
    lines += [f"pose x{j} in [-2, 2]" for j in range(8)]
    lines += [f"command q{j} in [-pi, pi] periodic" for j in range(8)]
    lines += [f"equation x{j} - sin(q{j}) = 0" for j in range(8)]
    return lines


def expression(size):
    n = max(2, size // 12)
    leaves = [f"{(k % 97) + 1}.5*x" if k % 3 == 0 else f"sin(q+{k % 89})" for k in range(n)]
    expr = balanced(leaves, 0, n)
    return ["robot Expression", "pose x in [-1, 1]", "command q in [-pi, pi] periodic",
            f"equation x - 1e-9*{expr} = 0"]


def lets(size):
    lines = ["robot Lets", "pose x in [-1, 1]", "command q in [-1, 1]"]
    total = 0
    i = 0
    while total < size:
        line = f"let a{i} = x*{i % 1000 + 1} + q - {i}"
        lines.append(line)
        total += len(line) + 1
        i += 1
    # Sum the lets in groups so that no sum is deeper than the parser's limit.
    names = [f"a{k}" for k in range(i)]
    level = 0
    while len(names) > 1:
        grouped = []
        for g in range(0, len(names), 100):
            lines.append(f"let s{level}_{g} = " + " + ".join(names[g:g + 100]))
            grouped.append(f"s{level}_{g}")
        names = grouped
        level += 1
    lines.append(f"equation {names[0]} = 0")
    return lines


def variables(size):
    lines = ["robot Variables"]
    total = 0
    i = 0
    while total < size:
        line = f"pose x{i} in [-1, 1]"
        lines.append(line)
        total += len(line) + 1
        i += 1
    return lines


def constraint(size):
    atoms = []
    total = 0
    k = 0
    while total < size:
        atom = "((" + " + ".join(f"x*{(k + j) % 50 + 1}" for j in range(40)) + ") > -1000000)"
        atoms.append(atom)
        total += len(atom) + 5
        k += 1
    return ["robot Constraint", "pose x in [-1, 1]", "command q in [-1, 1]", "equation x - q = 0",
            "constraint " + " and ".join(atoms)]


def parens(size):
    # ( ... ((x + 1) + 1) ... + 1) > 0 repeated: each group a sum, 150 deep (under the
    # nesting limit of 200), in a conjunction.
    depth = 150
    atom = "(" * depth + "x" + "".join(f" + {j})" for j in range(depth)) + " > -1000000"
    atoms = []
    total = 0
    while total < size:
        atoms.append("(" + atom + ")")
        total += len(atom) + 7
    return ["robot Parens", "pose x in [-1, 1]", "command q in [-1, 1]", "equation x - q = 0",
            "constraint " + " and ".join(atoms)]


SHAPES = {"constants": constants, "periodic": periodic, "expression": expression, "lets": lets,
          "variables": variables, "constraint": constraint, "parens": parens}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    out, size = sys.argv[1], int(sys.argv[2])
    os.makedirs(out, exist_ok=True)
    for name, make in SHAPES.items():
        path = os.path.join(out, f"{name}_{size}.robot")
        with open(path, "w") as f:
            f.write("\n".join(make(size)) + "\n")
        print(path)


if __name__ == "__main__":
    main()
