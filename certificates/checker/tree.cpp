// tree.cpp — trusted core: the record rules of the search tree (FORMAT.md, "Search
// tree"): contractions, bisections, discarded cells, and the leaves with their output
// boxes, claimed signs and the proofs of P1, P2 and the inner test.
#include "check.h"

namespace cc {

// The search tree in depth-first preorder: a stack of cells, left child on top.
void Checker::tree() {
  std::vector<Box> stack{root};
  for (;;) {
    rd.next();
    if (rd.kind() == "end-tree") break;
    if (stack.empty()) malformed(rec(), "expected 'end-tree': the search tree is complete");
    Box cell = std::move(stack.back());
    stack.pop_back();
    while (rd.kind() == "P") {
      contraction(cell);
      rd.next();
    }
    const std::string k(rd.kind());
    if (k == "B") {
      bisection(cell, stack);
    } else if (k == "X") {
      discard(cell);
    } else if (k == "U" || k == "S" || k == "N") {
      leaf(cell);
    } else if (k == "end-tree") {
      malformed(rec(), "node without an outcome record");
    } else {
      malformed(rec(), "unknown record type '" + k + "'");
    }
  }
  rd.count(2);
  if (!stack.empty())
    reject("the search tree leaves " + std::to_string(stack.size()) + " cell(s) uncovered");
  if (rd.integer() != int64_t(R.size())) reject("end-tree: wrong number of leaves");
}

// P: refutes both closed slabs outside [LO, HI], then narrows the cell to it.
void Checker::contraction(Box& cell) {
  rd.count(4);
  const long v = index(nv);
  const Box lh = intervals(&cell[2 * v], 1, kContractionGridBits);  // binary: on a coarser grid
  const double lo = cell[2 * v];
  const double hi = cell[2 * v + 1];
  if (!within(lo, hi, lh[0], lh[1])) reject("contraction is not inside the cell");
  Box slab = cell;
  put(slab, v, lo, lh[0]);
  if (lh[0] > lo) prove_refuted(slab, "cannot refute the slab below the contraction");
  put(slab, v, lh[1], hi);
  if (lh[1] < hi) prove_refuted(slab, "cannot refute the slab above the contraction");
  put(cell, v, lh[0], lh[1]);
}

void Checker::bisection(Box& cell, std::vector<Box>& stack) {
  rd.count(3);
  const long v = index(nv);
  const double x = rd.end(cell[2 * v], cell[2 * v + 1], false, kMiddleOffset);
  if (!(cell[2 * v] < x && x < cell[2 * v + 1]))
    reject("bisection point not strictly inside the cell");
  stack.push_back(cell);
  stack.back()[2 * v] = x;  // right child below, left child on top
  cell[2 * v + 1] = x;
  stack.push_back(std::move(cell));
}

// X: the cell holds no feasible solution. The checker runs its whole refutation procedure
// whatever the hint says, so the hint is a label: its form (hs, eq<i>, c<k>, canonical
// indices) is checked, and the equation or constraint it names must exist (FORMAT.md,
// "X <HINT>").
void Checker::discard(const Box& cell) {
  rd.count(2);
  const std::string_view h = rd.word();
  size_t digits = 0;  // where the index of eq<i> or c<k> starts
  if (h.compare(0, 2, "eq") == 0) digits = 2;
  if (h[0] == 'c') digits = 1;
  const bool indexed = digits > 0 && h.size() > digits;
  const long i = indexed ? parse_int(h.substr(digits), rec()) : -1;
  const long named = digits == 2 ? m.n() : long(m.constraints.size());
  if (h != "hs" && (i < 0 || i >= named))
    malformed(rec(), "bad hint '" + std::string(h) + "'");
  prove_refuted(cell, "cannot refute the discarded cell");
}

void Checker::leaf(const Box& cell) {
  if (rd.size() < 3) malformed(rec(), std::string(rd.kind()) + " record: too few fields");
  if (rd.integer() != int64_t(R.size())) reject("output box ids must be 0, 1, 2, ... in order");
  if (rd.kind() == "S") {
    solution_leaf(cell);
    return;
  }
  rd.count(3);
  // N (a cell a stopped search never reached) is checked and used as U is: its box is the
  // cell, it may hold solutions, and the bound counts it in every compatible class.
  const bool unexplored = rd.kind() == "N";
  const std::string signs(rd.word());
  store(signs, cell.data(), false);
  prove([this, signs, cell](Prover& pr) {
    pr.load(cell.data());
    return signs_proved(pr, signs, false);
  });
  ++(unexplored ? out.unexplored : out.undecided);
  out.wide_undecided += !unexplored && !at_most_eps(cell);
}

// The search ends a branch undecided only when every width is at most eps (FORMAT.md,
// "U"): hi − lo ≤ eps exactly, from its rounded value s and the exact error e (TwoSum).
bool Checker::at_most_eps(const Box& cell) const {
  for (int v = 0; v < nv; ++v) {
    const double a = cell[2 * v + 1], b = -cell[2 * v];
    const double s = a + b, bb = s - a, e = (a - (s - bb)) + (b - bb);
    if (!(s < out.eps || (s == out.eps && e <= 0))) return false;
  }
  return true;
}

void Checker::solution_leaf(const Box& cell) {
  // A binary record has no preconditioners: the prover computes its own.
  const size_t nn = rd.binary() ? 0 : size_t(n) * n;
  const size_t weights = version == 1 ? 0 : 2 * size_t(n);
  rd.count(3 + 4 * size_t(n) + 3 * nn + weights);
  const std::string_view signs = rd.word();
  // Q~ is coded against the cell's commands, IMAGE against Q~.
  const Box Q = intervals(commands_of(cell.data()).data(), n);
  const Box img = intervals(Q.data(), n);
  const std::vector<double> C = rd.reals(nn);
  const std::vector<double> CX = rd.reals(nn);
  const std::vector<double> CQ = rd.reals(nn);
  // Version 1 has no weights (unscaled dominance); a binary record codes them on [1, 2].
  std::vector<double> DX(n, 1.0), DQ(n, 1.0);
  for (int j = 0; version > 1 && j < n; ++j) DX[j] = rd.end(1, 2, false);
  for (int j = 0; version > 1 && j < n; ++j) DQ[j] = rd.end(1, 2, false);
  for (int j = 0; j < n; ++j)
    if (!(DX[j] > 0) || !(DQ[j] > 0)) reject("P2: a column weight is not positive");
  const Box B = solution_box(cell, Q, img);
  const std::string s(signs);
  // Queued before store() checks SIGNS: a record whose P1 fails and whose SIGNS is
  // malformed is rejected for P1, as when the proofs ran in line.
  prove([=](Prover& pr) {
    pr.load(cell.data());
    std::string why =
        unique_zero(pr, "P1", Q, C, img, "the Hansen-Sengupta image is not inside IMAGE");
    if (!why.empty()) return why;
    pr.load(B.data());
    const double* cx = CX.empty() ? nullptr : CX.data();  // binary: the checker's own
    const double* cq = CQ.empty() ? nullptr : CQ.data();
    if (const char* w = pr.regular(cx, cq, DX.data(), DQ.data()))
      return std::string("P2: ") + w;
    if (pr.evaluator().feasible(pr.box.data()) != 2)
      return "inner test: a constraint is not True on the box" + show(B);
    return signs_proved(pr, s, true);
  });
  store(s, B.data(), true);
  ++out.solutions;
}

// The output box of an S record: the cell's poses with IMAGE's commands, once Q~ and IMAGE
// are tied to the cell and to the declared domain (checks 1 and 3 of FORMAT.md).
Box Checker::solution_box(const Box& cell, const Box& Q, const Box& img) {
  Box B = cell;
  for (int j = 0; j < n; ++j) {
    const int v = m.command[j];
    const double qlo = Q[2 * j];
    const double qhi = Q[2 * j + 1];
    if (!within(qlo, qhi, cell[2 * v], cell[2 * v + 1]))
      reject("coverage: the cell's " + m.vars[v].name + " is not inside Q~");
    if (!within(qlo, qhi, img[2 * j], img[2 * j + 1])) reject("IMAGE is not inside Q~");
    if (!periodic[v] && !within_domain(v, img[2 * j], img[2 * j + 1]))
      reject("IMAGE leaves the declared domain of " + m.vars[v].name);
    put(B, v, img[2 * j], img[2 * j + 1]);
  }
  // Each non-periodic pose variable must meet the declared domain (a periodic one does,
  // modulo 2π): a box outside it may not count for the bound.
  for (int v : m.pose)
    if (!periodic[v] && !meets_domain(B.data(), v))
      reject("solution box misses the declared domain of " + m.vars[v].name + show(B));
  return B;
}

// A Hansen–Sengupta step on pr.box proves `claim` (P1 or P3): its image H lies in int Q~
// (so f has a unique zero in Q~) and in `target` (one lo/hi pair per command). Returns
// "" when it does, else the rejection.
std::string Checker::unique_zero(Prover& pr, const std::string& claim, const Box& Q,
                        const std::vector<double>& C, const Box& target,
                        const std::string& outside, bool pose) const {
  const double* c = C.empty() ? nullptr : C.data();  // binary records: the checker's own
  if (const char* why = pr.newton(Q.data(), c, pose)) return claim + ": " + why;
  for (int j = 0; j < n; ++j) {
    const Ival& y = pr.y[j];
    if (!inside(y, Q[2 * j], Q[2 * j + 1], true))
      return claim + ": the Hansen-Sengupta image is not inside the interior of Q~";
    if (!inside(y, target[2 * j], target[2 * j + 1], false)) return claim + ": " + outside;
  }
  return std::string();
}

// Parses SIGNS and stores the output box with its claimed signs; signs_proved() proves
// them (a claim that fails rejects the whole certificate).
bool Checker::well_formed(std::string_view s) const {
  if (p == 0) return s == ".";  // SIGNS: p characters of "+-0", or "." when there is no factor
  return s.size() == size_t(p) && s.find_first_not_of("+-0") == s.npos;
}

void Checker::store(std::string_view s, const double* box, bool solution) {
  if (!well_formed(s)) malformed(rec(), "bad SIGNS field '" + std::string(s) + "'");
  uint32_t pos = 0, neg = 0;
  for (int i = 0; i < p; ++i)
    if (s[i] != '0') (s[i] == '+' ? pos : neg) |= 1u << i;
  R.add_box(box);
  R.pos.push_back(pos);
  R.neg.push_back(neg);
  R.solution.push_back(solution);
}

// Proves every claimed sign of SIGNS on pr.box; `jac`: its Jacobians are already
// computed. Returns "" when every sign holds (or SIGNS is malformed: store() says so),
// else the rejection.
std::string Checker::signs_proved(Prover& pr, const std::string& s, bool jac) const {
  if (!well_formed(s)) return std::string();
  Ival val;
  for (int i = 0; i < p; ++i) {
    if (s[i] == '0') continue;
    const std::string which = "factor " + std::to_string(i + 1);
    if (!pr.factor(factors[i], jac, val)) return which + " is not defined on the box";
    // A proved non-user factor leaves the Jacobians of the box computed, for the next ones.
    if (factors[i].kind != Factor::User) jac = true;
    if (val.sign() != (s[i] == '+' ? 1 : -1))
      return "sign '" + std::string(1, s[i]) + "' of " + which + " not proved";
  }
  return std::string();
}

}  // namespace cc
