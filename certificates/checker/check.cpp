// check.cpp — trusted core: the record rules. Reads a certificate of `aspects solve` record
// by record and re-verifies every claim with the checker's own parser, evaluator and proofs
// (FORMAT.md is the specification). Each record's structure is checked here, in order; its
// interval proofs run in line, or are queued (proof_batch.cpp) and judged in record order.
// It keeps only what later sections need: the output boxes as doubles with their claimed
// signs (each proved), the union-find of the links and the CSNC of each box.
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>
#include <tuple>

#include "checker.h"

using namespace cc;

namespace {

using Box = std::vector<double>;  // lo/hi pairs, one per variable (or per command)

// Variable (or command) i of box b := [lo, hi].
void put(Box& b, int i, double lo, double hi) {
  b[2 * i] = lo;
  b[2 * i + 1] = hi;
}

// lo <= a and b <= hi: [a, b] inside [lo, hi], on exact doubles.
bool within(double lo, double hi, double a, double b) { return lo <= a && b <= hi; }

// y ⊆ int [lo, hi] (strict) or y ⊆ [lo, hi], comparing the MPFI ends with exact doubles.
bool inside(const Ival& y, double lo, double hi, bool strict) {
  const int a = mpfr_cmp_d(y.L(), lo);
  const int b = mpfr_cmp_d(y.R(), hi);
  return strict ? a > 0 && b < 0 : a >= 0 && b <= 0;
}

struct Checker {
  LineReader rd;
  Verdict& out;
  Model m;
  std::unique_ptr<Evaluator> ev;  // the header's constants, and the proofs run in line
  std::unique_ptr<Prover> prover;  // the proofs in line (--trusted-only): on `ev`
  int threads = 1;
  int n = 0, nv = 0, p = 0;    // equations, variables, factors
  int version = 0;             // 1: P2 without column weights (D = 1); 2: with DX, DQ
  std::vector<Ival> dlo, dhi;  // enclosures of the declared bounds
  std::vector<bool> periodic;
  std::vector<Factor> factors;
  Box root;                      // the root cell (domain record)
  OutBoxes R;                    // the output boxes, in id order
  UnionFind linked;              // output boxes joined by verified links
  std::vector<int32_t> csnc_of;  // the CSNC of each output box (-1: none)
  std::vector<int64_t> sizes;    // the CSNCs' sizes
  std::pair<long, long> last_link{-1, -1};             // records are sorted: (A, B)
  std::tuple<long, long, long> last_witness{-1, -1, -1};  // (CSNC, A, B)
  std::tuple<long, long, long> last_assembly{-1, -1, -1};  // (CSNC, A, B)
  int work_base = 29;
  size_t pairs_ = 0;  // pairs of M, for the statistics
  double graph_seconds_ = 0;  // building and sweeping M, for the statistics
  // Last, so that it is destroyed first: its helper threads finish the proofs they hold
  // (which read the members above) before anything they read is gone, whatever was thrown.
  std::unique_ptr<ProofBatch> batch;

  Checker(FILE* f, Verdict& v) : rd(f), out(v) {}
  long rec() const { return rd.record(); }
  [[noreturn]] void reject(const std::string& why) { rejected(rec(), why); }
  // The next field: an index in 0..limit-1.
  long index(size_t limit) {
    const int64_t v = rd.integer();
    if (v < 0 || uint64_t(v) >= limit) reject("index " + std::to_string(v) + " out of range");
    return long(v);
  }
  // The work the check may take: 2^29 units plus 2^10 per byte read, a unit being one node
  // evaluation weighted by the precision (prec/64 + 2 limbs). A hostile certificate (a model
  // of 10^5 nodes, refutations that bisect 4096 boxes) is stopped within minutes, not days.
  // CHECK_CERT_WORK_BASE (log2 of the base) changes how long it may work, never the verdict.
  // Each queued proof carries the limit of its record; the header's own evaluations (the
  // declared bounds) are not limited.
  uint64_t work_limit() const {
    const uint64_t weight = uint64_t(mpfr_get_default_prec() / 64 + 2);
    const uint64_t base = uint64_t(1) << work_base;
    const uint64_t per_byte = uint64_t(1) << 10;
    return (base + per_byte * rd.bytes()) / weight;
  }
  // Proves a claim of the record read last: in line, or queued (proof_batch.cpp) to run
  // later, maybe on another thread, so it captures what it needs by value. Either way the
  // first failure in record order is the verdict, and a proof past the work limit of its
  // record is rejected at that record.
  void prove(const ProofBatch::Proof& proof) {
    if (batch) return batch->add(rec(), work_limit(), proof);
    ev->work_limit = work_limit();
    const std::string why = proof(*prover);
    if (!why.empty()) reject(why);
  }
  void flush() {
    if (batch) batch->flush();
  }
  // A proof that `box` holds no feasible solution; `why` + the box is the rejection otherwise.
  void prove_refuted(const Box& box, const char* why) {
    prove([this, box, why](Prover& pr) -> std::string {
      pr.load(box.data());
      return pr.refute() ? std::string() : why + show(box);
    });
  }
  // hi - lo >= 2π, proved: a periodic root cell then covers every angle (a shorter one,
  // declared with a rounded pi, would leave a gap that splits an aspect at the seam).
  bool spans_period(double lo, double hi) {
    Ival w;
    mpfi_set_d(w, hi);
    mpfi_sub_d(w, w, lo);
    return mpfr_cmp(w.L(), ev->two_pi.R()) >= 0;
  }
  // Variable v of `box` meets the inner enclosure of its declared domain.
  bool meets_domain(const double* box, int v) const {
    const bool lo_below = mpfr_cmp_d(dlo[v].R(), box[2 * v + 1]) <= 0;
    return lo_below && mpfr_cmp_d(dhi[v].L(), box[2 * v]) >= 0;
  }
  // [lo, hi] lies in the inner enclosure of the declared domain of v.
  bool within_domain(int v, double lo, double hi) const {
    return mpfr_cmp_d(dlo[v].R(), lo) <= 0 && mpfr_cmp_d(dhi[v].L(), hi) >= 0;
  }
  std::string show(const Box& b) const {  // a box, for messages
    std::string s;
    for (int v = 0; v < nv; ++v) {
      char buf[64];
      const char* sep = v ? ", " : " (";
      const char* name = m.vars[v].name.c_str();
      std::snprintf(buf, sizeof buf, "%s%s in [%.17g, %.17g]", sep, name, b[2 * v], b[2 * v + 1]);
      s += buf;
    }
    return s + ")";
  }

  void header() {
    rd.next();
    if (rd.size() != 2 || rd.kind() != "aspects-certificate")
      malformed(rec(), "not an aspects certificate");
    const std::string_view v = rd.word();
    if (v != "1" && v != "2")
      malformed(rec(), "unknown certificate version '" + std::string(v) + "'");
    version = v == "1" ? 1 : 2;
    rd.expect({"tool", "aspects"}, 1);  // the writer's version: free text (FORMAT.md)
    read_model();
    read_domain();
    const int64_t count = rd.expect({"factors"}, 1).integer();
    if (count < 0 || count > 20) reject("number of factors out of range 0..20");
    p = int(count);
    for (int i = 0; i < p; ++i) factors.push_back(read_factor());
    rd.expect({"tree"}, 0);
    R.nv = nv;
  }

  // The model record, its text, the precision and the declared bounds.
  void read_model() {
    rd.expect({"model"}, 2);
    const long model_rec = rec();
    const int64_t bytes = rd.integer();
    const std::string sha(rd.word());
    if (bytes < 0 || bytes > (1 << 20)) malformed(rec(), "model size out of range");
    if (sha.size() != 64 || sha.find_first_not_of("0123456789abcdef") != std::string::npos)
      malformed(rec(), "bad SHA-256 field");
    const std::string text = rd.raw(size_t(bytes));
    rd.expect({"end-model"}, 0);
    out.model_sha = sha256_hex(text);
    if (out.model_sha != sha) rejected(model_rec, "SHA-256 of the embedded model does not match");
    const int64_t prec = rd.expect({"precision"}, 1).integer();
    if (prec < 24 || prec > 4096) malformed(rec(), "precision out of range 24..4096");
    mpfr_set_default_prec(mpfr_prec_t(prec));
    try {
      m = parse_model(text);
      // A limit of the checker, not of the format: the evaluator keeps about nodes·(variables
      // + 5) intervals of `prec` bits (and MPFR aborts when out of memory).
      const double nodes = double(m.nodes.size());
      if (nodes * double(m.vars.size() + 5) * double(prec / 64 + 2) > double(1 << 22))
        rejected(model_rec, "the embedded model is too large for the checker at this precision");
      ev.reset(new Evaluator(m));
    } catch (const ModelError& e) {
      malformed(model_rec, std::string("embedded model: ") + e.what());
    }
    n = m.n();
    nv = int(m.vars.size());
    out.robot = m.name;
    read_bounds(model_rec);
  }

  // The declared domain of every variable, enclosed at the certificate's precision.
  void read_bounds(long model_rec) {
    dlo.resize(nv);
    dhi.resize(nv);
    for (int v = 0; v < nv; ++v) {
      const Var& x = m.vars[v];
      const std::string what = "embedded model: ";
      if (!ev->constant(x.lo, dlo[v]) || !ev->constant(x.hi, dhi[v]))
        malformed(model_rec, what + "domain bound of '" + x.name + "' is not a finite number");
      const bool reversed = mpfr_cmp(dlo[v].L(), dhi[v].R()) > 0;
      if (reversed || mpfr_cmp(dlo[v].R(), dhi[v].L()) > 0)
        malformed(model_rec, what + "empty or reversed domain of '" + x.name + "'");
      // Exactly, not by intervals: `[-3.1415926, 3.1415926] periodic` passes an interval test
      // at 24 bits (and a longer decimal at any precision) and leaves a gap at the seam.
      if (x.periodic && !exactly_one_period(m, x))
        malformed(model_rec, what + "periodic domain of '" + x.name +
                                 "' is not one period (exactly: a*pi + b, rational a, b)");
      periodic.push_back(x.periodic);
    }
  }

  // tau and eps (range only: informational) and the root cell.
  void read_domain() {
    if (!(rd.expect({"tau"}, 1).real() >= 1)) malformed(rec(), "tau must be >= 1");
    out.eps = rd.expect({"eps"}, 1).real();
    if (!(out.eps > 0)) malformed(rec(), "eps must be > 0");
    root = rd.expect({"domain"}, 2 * size_t(nv)).intervals(nv);
    for (int v = 0; v < nv; ++v) {
      const std::string& name = m.vars[v].name;
      // The root cell is the declared domain rounded outward to doubles, nothing more: it
      // covers every configuration, and it cannot hold boxes of another (wider) domain.
      if (root[2 * v] != dlo[v].lo() || root[2 * v + 1] != dhi[v].hi())
        reject("root cell is not the declared domain of '" + name + "' rounded outward to doubles");
      if (periodic[v] && !spans_period(root[2 * v], root[2 * v + 1]))
        reject("root cell of periodic '" + name + "' does not provably span 2*pi");
    }
  }

  // factor KIND [ARG]: detFx, detFq, diagFx i, diagFq i (1-based entry), user k (1-based).
  Factor read_factor() {
    static const std::string_view kinds[] = {"detFx", "detFq", "diagFx", "diagFq", "user"};
    rd.next();
    const std::string_view k = rd.size() > 1 ? rd.word() : std::string_view();
    const long kind = std::find(kinds, kinds + 5, k) - kinds;  // in Factor::Kind order; 5: none
    const bool with_arg = kind >= Factor::DiagFx && kind <= Factor::User;
    if (rd.kind() != "factor" || rd.size() != (with_arg ? 3u : 2u))
      malformed(rec(), "expected 'factor KIND [ARG]'");
    if (kind == 5) malformed(rec(), "unknown factor kind '" + std::string(k) + "'");
    Factor fa{Factor::Kind(kind), 0};
    if (with_arg) {
      const size_t entries = fa.kind == Factor::User ? m.factors.size() : size_t(n);
      fa.arg = int(index(1 + entries)) - 1;
    }
    if (fa.arg < 0) reject("factor indices are 1-based");
    if (fa.kind == Factor::User) out.user_factors = true;
    if (fa.kind == Factor::DiagFx || fa.kind == Factor::DiagFq) require_triangular(fa.kind, k);
    return fa;
  }

  // det = product of the diagonal needs every entry above, or every entry below, the diagonal
  // to be structurally zero (equation r does not mention variable c).
  void require_triangular(Factor::Kind kind, std::string_view name) {
    const std::vector<int>& cols = kind == Factor::DiagFx ? m.pose : m.command;
    bool upper_zero = true;
    bool lower_zero = true;
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        if (!(m.nodes[m.eqs[r]].dep >> cols[c] & 1)) continue;
        upper_zero = upper_zero && c <= r;
        lower_zero = lower_zero && c >= r;
      }
    if (!upper_zero && !lower_zero)
      reject(std::string(name) + ": the matrix is not structurally triangular");
  }

  // The search tree in depth-first preorder: a stack of cells, left child on top.
  void tree() {
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
  void contraction(Box& cell) {
    rd.count(4);
    const long v = index(nv);
    const Box lh = rd.intervals(1);
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

  void bisection(Box& cell, std::vector<Box>& stack) {
    rd.count(3);
    const long v = index(nv);
    const double x = rd.real();
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
  void discard(const Box& cell) {
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

  void leaf(const Box& cell) {
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
  bool at_most_eps(const Box& cell) const {
    for (int v = 0; v < nv; ++v) {
      const double a = cell[2 * v + 1], b = -cell[2 * v];
      const double s = a + b, bb = s - a, e = (a - (s - bb)) + (b - bb);
      if (!(s < out.eps || (s == out.eps && e <= 0))) return false;
    }
    return true;
  }

  void solution_leaf(const Box& cell) {
    const size_t nn = size_t(n) * n;
    const size_t weights = version == 1 ? 0 : 2 * size_t(n);
    rd.count(3 + 4 * size_t(n) + 3 * nn + weights);
    const std::string_view signs = rd.word();
    const Box Q = rd.intervals(n);
    const Box img = rd.intervals(n);
    const std::vector<double> C = rd.reals(nn);
    const std::vector<double> CX = rd.reals(nn);
    const std::vector<double> CQ = rd.reals(nn);
    const std::vector<double> ones(n, 1.0);  // version 1: unscaled dominance
    const std::vector<double> DX = version == 1 ? ones : rd.reals(n);
    const std::vector<double> DQ = version == 1 ? ones : rd.reals(n);
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
      if (const char* w = pr.regular(CX.data(), CQ.data(), DX.data(), DQ.data()))
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
  Box solution_box(const Box& cell, const Box& Q, const Box& img) {
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
  std::string unique_zero(Prover& pr, const std::string& claim, const Box& Q,
                          const std::vector<double>& C, const Box& target,
                          const std::string& outside, bool pose = false) const {
    if (const char* why = pr.newton(Q.data(), C.data(), pose)) return claim + ": " + why;
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
  bool well_formed(std::string_view s) const {
    if (p == 0) return s == ".";  // SIGNS: p characters of "+-0", or "." when there is no factor
    return s.size() == size_t(p) && s.find_first_not_of("+-0") == s.npos;
  }
  void store(std::string_view s, const double* box, bool solution) {
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
  std::string signs_proved(Prover& pr, const std::string& s, bool jac) const {
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

  // `head COUNT`, then COUNT records of kind `kind`, each checked by record(i).
  template <class Record>
  void section(const char* head, const char* kind, Record record) {
    const int64_t total = rd.require({head}, 1).integer();
    if (total < 0) malformed(rec(), "negative count");
    for (int64_t i = 0; i < total; ++i) {
      rd.next();
      if (rd.kind() != kind) {
        const std::string announced = " (" + std::to_string(total) + " announced)";
        malformed(rec(), std::string("expected a ") + kind + " record" + announced);
      }
      record(i);
    }
  }

  // SHIFT: one character of "-0+" per variable, k_v = -1, 0, +1.
  std::vector<int> shifts() {
    const std::string_view s = rd.word();
    if (s.size() != size_t(nv) || s.find_first_not_of("-0+") != s.npos)
      malformed(rec(), "bad SHIFT field");
    std::vector<int> k(nv);
    for (int v = 0; v < nv; ++v) k[v] = int(s[v] == '+') - int(s[v] == '-');
    return k;
  }

  // Variable v of box a ∩ (box b + 2πk), the shifted ends of b rounded inward (FORMAT.md,
  // "Certified links"); empty when lo > hi.
  std::pair<double, double> inner(long a, long b, int v, int k) {
    double blo = R.box(b)[2 * v];
    double bhi = R.box(b)[2 * v + 1];
    if (k) {
      Ival t;
      shift_by_periods(t, ev->two_pi, k, blo);
      blo = t.hi();
      shift_by_periods(t, ev->two_pi, k, bhi);
      bhi = t.lo();
    }
    return {std::max(R.box(a)[2 * v], blo), std::min(R.box(a)[2 * v + 1], bhi)};
  }

  // K: box A and box B shifted by 2πk share a solution (P3).
  void link() {
    rd.count(4 + 3 * size_t(n) + size_t(n) * n);
    const long a = index(R.size());
    const long b = index(R.size());
    if (!(a < b)) reject("link needs A < B");
    if (!R.solution[a] || !R.solution[b])
      reject("link between boxes that are not both solution boxes");
    if (std::make_pair(a, b) <= last_link) reject("links not sorted by (A, B) or repeated");
    const std::vector<int> k = shifts();
    const std::vector<double> w = rd.reals(n);
    const Box Q = rd.intervals(n);
    const std::vector<double> C = rd.reals(size_t(n) * n);
    Box X(2 * nv);  // the intersection, then the witness pose with its commands
    for (int v = 0; v < nv; ++v) {
      if (k[v] && !periodic[v]) reject("shift on a non-periodic variable");
      std::tie(X[2 * v], X[2 * v + 1]) = inner(a, b, v, k[v]);
      if (!(X[2 * v] <= X[2 * v + 1])) reject("the linked boxes do not meet");
    }
    Box commands(2 * n);
    for (int j = 0; j < n; ++j) {
      const int v = m.pose[j];
      if (!within(X[2 * v], X[2 * v + 1], w[j], w[j]))
        reject("witness outside the boxes' intersection");
      put(X, v, w[j], w[j]);
      put(commands, j, X[2 * m.command[j]], X[2 * m.command[j] + 1]);
    }
    prove([=](Prover& pr) {
      pr.load(X.data());
      return unique_zero(pr, "P3", Q, C, commands, "the command is not in both boxes");
    });
    linked.unite(int(a), int(b));  // if the proof fails, the certificate is rejected
    last_link = {a, b};
    ++out.links;
  }

  // csnc K SIZE IDS: component K, listed by decreasing size, is connected by verified links.
  void csnc(int64_t k) {
    if (rd.size() < 3) malformed(rec(), "expected a csnc record");
    if (rd.integer() != k) reject("components must be numbered 0, 1, 2, ...");
    const int64_t size = rd.integer();
    if (size < 1 || rd.size() != 3 + size_t(size))
      malformed(rec(), "csnc: SIZE does not match the ids");
    if (!sizes.empty() && size > sizes.back()) reject("components not listed by decreasing size");
    sizes.push_back(size);
    long prev = -1;
    for (int64_t i = 0; i < size; ++i) {
      const long id = index(R.size());
      if (id <= prev) reject("component ids not increasing");
      if (!R.solution[id]) reject("component holds a box that is not a solution box");
      if (csnc_of[id] >= 0) reject("box " + std::to_string(id) + " is in two components");
      csnc_of[id] = int32_t(k);
      if (prev >= 0 && linked.find(int(id)) != linked.find(int(prev)))
        reject("component is not connected by certified links");
      prev = id;
    }
  }

  // CSNC A B SHIFT of a W record (`w`: shifts on poses) or a V record (shifts on commands):
  // after `last` in (CSNC, A, B) order, A < B solution boxes of the CSNC. k := SHIFT.
  std::tuple<long, long, long> pair_in_csnc(bool w, const std::tuple<long, long, long>& last,
                                           std::vector<int>& k) {
    const long c = index(sizes.size());
    const long a = index(R.size());
    const long b = index(R.size());
    k = shifts();
    const std::string sorted = "witnesses not sorted by (CSNC, A, B) or repeated";
    if (std::make_tuple(c, a, b) <= last) reject(w ? sorted : "assembly " + sorted);
    if (!(a < b)) reject("witness needs A < B");
    if (!R.solution[a] || !R.solution[b]) reject("witness boxes are not both solution boxes");
    if (csnc_of[a] != c || csnc_of[b] != c) reject("witness boxes are not both in the named CSNC");
    const std::string where = w ? "witness shift on a command" : "assembly shift on a pose";
    for (int v = 0; v < nv; ++v)
      if (k[v] && (!periodic[v] || m.vars[v].pose != w))
        reject(where + " or a non-periodic variable");
    return {c, a, b};
  }

  // W CSNC A B SHIFT (FORMAT.md, "Cuspidality witnesses"): two solution boxes of one CSNC
  // whose poses overlap and whose commands are disjoint.
  void witness() {
    rd.count(5);
    std::vector<int> k;
    long c, a, b;
std::tie(c, a, b) = pair_in_csnc(true, last_witness, k);
    for (int v : m.pose) {
      const std::pair<double, double> x = inner(a, b, v, k[v]);
      if (!(x.first <= x.second)) reject("witness poses do not overlap");
    }
    const auto apart_in = [&](int v) { return apart(a, b, v); };
    if (std::none_of(m.command.begin(), m.command.end(), apart_in))
      reject("witness commands are not disjoint");
    out.cuspidal_csncs += c != std::get<0>(last_witness);
    last_witness = {c, a, b};
    ++out.cuspidal;
  }

  // V CSNC A B SHIFT Q* X~A CA X~B CB (FORMAT.md, "Assembly-mode witnesses"): q* lies in the
  // commands of box A and of box B + 2πk, and f(·, q*) has a zero in each box's poses, proved
  // by Hansen–Sengupta in x; the two poses are disjoint, so q* has two poses in one CSNC.
  void assembly() {
    rd.count(5 + 5 * size_t(n) + 2 * size_t(n) * n);
    std::vector<int> k;
    long c, a, b;
std::tie(c, a, b) = pair_in_csnc(false, last_assembly, k);
    const auto apart_in = [&](int v) { return apart(a, b, v); };
    if (std::none_of(m.pose.begin(), m.pose.end(), apart_in))
      reject("assembly poses are not disjoint");
    const std::vector<double> q = rd.reals(n);
    Box X(2 * nv);  // the point command q*; the poses are the unknowns
    for (int j = 0; j < n; ++j) {
      const int v = m.command[j];
      const std::pair<double, double> I = inner(a, b, v, k[v]);
      if (!within(I.first, I.second, q[j], q[j])) reject("q* is not in both boxes' commands");
      put(X, v, q[j], q[j]);
    }
    for (long id : {a, b}) {
      const Box Xt = rd.intervals(n);
      const std::vector<double> C = rd.reals(size_t(n) * n);
      Box poses(2 * n);
      for (int j = 0; j < n; ++j) {
        const int v = m.pose[j];
        if (!periodic[v] && !within_domain(v, Xt[2 * j], Xt[2 * j + 1]))
          reject("x~ leaves the declared domain of " + m.vars[v].name);
        put(poses, j, R.box(id)[2 * v], R.box(id)[2 * v + 1]);
      }
      prove([=](Prover& pr) {
        pr.load(X.data());
        return unique_zero(pr, "assembly", Xt, C, poses, "the pose is not in the box", true);
      });
    }
    last_assembly = {c, a, b};
    ++out.assembly;
  }

  // Variable v of boxes a and b is disjoint, modulo 2π when v is periodic: for one m, b + 2πm
  // lies strictly above a and b + 2π(m − 1) strictly below it (shifted ends rounded outward;
  // the candidates m come from double arithmetic, only the MPFI comparisons decide).
  bool apart(long a, long b, int v) {
    const double al = R.box(a)[2 * v];
    const double ah = R.box(a)[2 * v + 1];
    const double bl = R.box(b)[2 * v];
    const double bh = R.box(b)[2 * v + 1];
    if (!periodic[v]) return ah < bl || bh < al;
    const double guess = std::ceil((ah - bl) / (2 * M_PI));
    if (!(std::fabs(guess) < 1048576)) return false;
    Ival t;
    for (long m = long(guess) - 1; m <= long(guess) + 1; ++m) {
      shift_by_periods(t, ev->two_pi, int(m), bl);
      if (!(ah < t.lo())) continue;
      shift_by_periods(t, ev->two_pi, int(m - 1), bh);
      if (t.hi() < al) return true;
    }
    return false;
  }

  // claim filtered, claim lower-bound and end; the bound is recomputed from the verified
  // boxes. Returns the number of pairs of the neighbourhood graph M.
  size_t claims(const CheckOptions& o) {
    if (rd.require({"claim", "filtered"}, 1).integer() != filtered_count(sizes))
      reject("claim filtered does not match the filtering rule");
    const int64_t claim = rd.expect({"claim", "lower-bound"}, 1).integer();
    const long claim_rec = rec();
    if (claim < 0) malformed(rec(), "negative lower bound");
    const int64_t records = rd.expect({"end"}, 1).integer();
    if (records != rec() - 1) malformed(rec(), "end: wrong record count");
    rd.expect_eof();
    flush();  // every proof judged before the bound
    // A real subdivision has a few neighbours per box, while S records that share one IMAGE
    // over many cells make M quadratic (10^5 boxes: 5·10^9 pairs): rejected instead.
    const size_t max_pairs = (size_t(1) << 22) + 64 * R.size();
    const auto t0 = std::chrono::steady_clock::now();
    std::unique_ptr<PairSweep> M;
    if (o.trusted_only) M.reset(new PlainSweep(R, periodic, ev->two_pi));
    else M.reset(new NeighbourSweep(R, periodic, ev->two_pi));
    uint32_t checkable = 0;  // the factors the checker can verify: all but `user` ones
    for (int i = 0; i < p; ++i)
      if (factors[i].kind != Factor::User) checkable |= 1u << i;
    size_t pairs = 0;
    try {
      out.recomputed = lower_bound(R, *M, (1u << p) - 1, max_pairs, &pairs, threads);
      out.checked = out.user_factors ? lower_bound(R, *M, checkable, max_pairs, nullptr, threads)
                                     : out.recomputed;
    } catch (const std::length_error& e) {
      if (std::string(e.what()) == "neighbourhood graph")
        rejected(claim_rec, "the neighbourhood graph has more than 2^22 + 64 pairs per box");
      rejected(claim_rec,
               "too many sign classes for the neighbourhood graph (2^32 + 2^10 steps per box)");
    }
    graph_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out.claimed = claim;
    if (claim > out.recomputed) {
      const std::string both = std::to_string(claim) + " exceeds the recomputed ";
      rejected(claim_rec, "claimed lower bound " + both + std::to_string(out.recomputed));
    }
    out.outcome = Outcome::Verified;
    if (claim > out.checked) {
      out.reason = "the claimed lower bound rests on user-supplied factors, which the checker "
                   "cannot verify; without them it is " + std::to_string(out.checked);
      if (o.trust_factors) out.reason += "; trusted (--trust-factors)";
      if (!o.trust_factors) out.outcome = Outcome::Unchecked;
    }
    return pairs;
  }

  void run(const CheckOptions& o) {
    const auto t0 = std::chrono::steady_clock::now();
    if (const char* e = std::getenv("CHECK_CERT_WORK_BASE"))
      work_base = std::max(10, std::min(40, std::atoi(e)));
    header();
    threads = o.threads > 0 ? o.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    // Each thread holds an evaluator of up to 2^22 units (read_model): at most 2^25 units in
    // all, so that many threads on a large model cannot exhaust memory. Fewer threads, never
    // another verdict.
    const double units = double(m.nodes.size()) * double(m.vars.size() + 5) *
                         double(mpfr_get_default_prec() / 64 + 2);
    threads = int(std::max(1.0, std::min(double(threads), double(1 << 25) / units)));
    if (o.trusted_only) threads = 1;
    if (o.trusted_only) prover.reset(new Prover(*ev));
    else batch.reset(new ProofBatch(m, threads, ev->work));
    try {
      body(o);
    } catch (const CertError&) {
      flush();  // a failed proof of an earlier record is the one to report
      throw;
    }
    out.cert_sha = rd.file_sha256();
    if (o.quiet) return;
    const auto elapsed = std::chrono::steady_clock::now() - t0;
    std::fprintf(stderr,
                 "check_cert: %ld refutations (%ld boxes), %llu node evaluations, %zu pairs in M "
                 "(%.2f s), recomputed lower bound %ld, %d thread%s, %.2f s\n",
                 batch ? batch->refutations() : prover->refutations,
                 batch ? batch->refute_boxes() : prover->refute_boxes,
                 (unsigned long long)(batch ? batch->work : ev->work),
                 pairs_, graph_seconds_, out.recomputed, threads, threads > 1 ? "s" : "",
                 std::chrono::duration<double>(elapsed).count());
  }

  // Every section after the header; the proofs are queued and judged in record order.
  void body(const CheckOptions& o) {
    tree();
    linked.reset(R.size());
    rd.next();
    section("links", "K", [&](int64_t) { link(); });
    csnc_of.assign(R.size(), -1);
    rd.next();
    section("csncs", "csnc", [&](int64_t k) { csnc(k); });
    out.csncs = long(sizes.size());
    rd.next();
    if (rd.kind() == "cuspidal") {  // an optional section
      section("cuspidal", "W", [&](int64_t) { witness(); });
      rd.next();
    }
    if (rd.kind() == "assembly") {  // an optional section
      section("assembly", "V", [&](int64_t) { assembly(); });
      rd.next();
    }
    pairs_ = claims(o);
  }
};

}  // namespace

const char* cc::outcome_name(Outcome o) {
  static const char* const names[] = {"VERIFIED", "REJECTED", "MALFORMED", "UNCHECKED"};
  return names[int(o)];
}

Verdict cc::check_certificate(FILE* f, const CheckOptions& o) {
  Verdict out;
  std::unique_ptr<Checker> c;
  try {
    c.reset(new Checker(f, out));
    c->run(o);
  } catch (const WorkLimit& e) {  // a limit of the checker: rejected, as out of memory
    out.outcome = Outcome::Rejected;
    out.record = c ? c->rec() : 0;
    out.reason = e.what();
  } catch (const CertError& e) {
    out.outcome = e.malformed ? Outcome::Malformed : Outcome::Rejected;
    out.record = e.record;
    out.reason = e.what();
  } catch (const std::bad_alloc&) {
    out.outcome = Outcome::Rejected;
    out.reason = "out of memory";
  } catch (const std::exception& e) {
    out.outcome = Outcome::Rejected;
    out.reason = std::string("internal error: ") + e.what();
  }
  return out;
}
