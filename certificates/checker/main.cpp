// main.cpp — `check_cert FILE.cert`: reads a certificate of `aspects solve` record by
// record and re-verifies every claim with the checker's own parser, evaluator and proofs
// (FORMAT.md is the specification). It keeps only what later sections need: the output
// boxes as doubles with their verified signs, and the union-find of verified links. Exit
// 0 only after everything verified (one VERIFIED line); 1 on the first failed
// verification (REJECTED) or out of memory; 2 on a malformed file (MALFORMED) or usage;
// 3 when every proof verified but the claimed bound needs a user-supplied factor
// (UNCHECKED; 0 with --trust-factors). `--json` prints the verdict as one JSON object.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <memory>
#include <tuple>
#include <new>

#include "cert_reader.h"
#include "graph.h"
#include "proofs.h"
#include "witness.h"

using namespace cc;

namespace {

using Fields = std::vector<std::string_view>;
using Box = std::vector<double>;  // lo/hi pairs, one per variable (or per command)

// Reads the reals of one record left to right. A group of intervals is parsed whole before
// its pairs are checked, so a bad real is reported before a reversed interval.
class RealCursor {
 public:
  RealCursor(const Fields& f, size_t first, long rec) : f_(f), next_(first), rec_(rec) {}
  std::vector<double> reals(size_t k) {
    std::vector<double> out(k);
    for (double& x : out) {
      x = parse_real(f_[next_], rec_);
      ++next_;
    }
    return out;
  }
  Box intervals(size_t k) {
    Box out = reals(2 * k);
    for (size_t j = 0; j < k; ++j)
      if (!(out[2 * j] <= out[2 * j + 1])) malformed(rec_, "interval with LO > HI");
    return out;
  }

 private:
  const Fields& f_;
  size_t next_;
  long rec_;
};

// lo <= a and b <= hi: [a, b] inside [lo, hi], on exact doubles.
bool within(double lo, double hi, double a, double b) { return lo <= a && b <= hi; }

// The kind a factor record names; an unknown name reads as User and is refused by the caller.
Factor::Kind factor_kind(const std::string& k) {
  if (k == "detFx") return Factor::DetFx;
  if (k == "detFq") return Factor::DetFq;
  if (k == "diagFx") return Factor::DiagFx;
  if (k == "diagFq") return Factor::DiagFq;
  return Factor::User;
}

// k of a SHIFT character: '+' 1, '-' -1, '0' 0.
int shift_of(char c) {
  if (c == '+') return 1;
  if (c == '-') return -1;
  return 0;
}

// The index prefix of a hint label: 2 for eq<i>, 1 for c<k>, 0 for anything else.
size_t hint_prefix(std::string_view h) {
  if (h.compare(0, 2, "eq") == 0) return 2;
  if (h[0] == 'c') return 1;
  return 0;
}

struct Checker {
  using Stack = std::vector<Box>;
  LineReader rd;
  Model m;
  std::unique_ptr<Evaluator> ev;
  std::unique_ptr<Prover> pr;
  int n = 0;
  int nv = 0;
  int p = 0;
  int version = 0;             // 1: P2 without column weights (D = 1); 2: with DX, DQ
  std::vector<Ival> dlo, dhi;  // enclosures of the declared bounds
  std::vector<bool> periodic;
  std::vector<Factor> factors;
  bool user_factors = false;
  OutBoxes R;
  Box root;  // the root cell (domain record)
  std::string model_sha;
  long solutions = 0;
  long undecided = 0;
  long unexplored = 0;
  long links = 0;
  std::vector<int32_t> csnc_of;
  size_t csncs_count = 0;  // CSNC of each output box (-1: none), from the csnc records
  long cuspidal = 0;
  long cuspidal_csncs = 0;
  int work_base = 29;

  explicit Checker(FILE* f) : rd(f) {}
  long rec() const { return rd.record(); }
  // The work the check may take grows with the bytes read: 2^29 units plus 2^10 per byte, a
  // unit being one node evaluation weighted by the precision (prec/64 + 2 limbs, as the
  // memory limit). Real certificates need a few units per byte; a hostile one (a model of
  // 10^5 nodes, refutations that bisect 4096 boxes) is stopped within minutes, not days.
  // CHECK_CERT_WORK_BASE (log2 of the base, 10..40) lowers it for the tests, or raises it;
  // either way it changes how long the checker may work, never what it accepts.
  void budget() {
    const uint64_t weight = uint64_t(mpfr_get_default_prec() / 64 + 2);
    const uint64_t base = uint64_t(1) << work_base;
    const uint64_t per_byte = uint64_t(1) << 10;
    ev->work_limit = (base + per_byte * rd.bytes()) / weight;
  }
  [[noreturn]] void reject(const std::string& why) { rejected(rec(), why); }
  int64_t I(std::string_view s) { return parse_int(s, rec()); }
  void count(const Fields& f, size_t k) {
    if (f.size() != k) malformed(rec(), std::string(f[0]) + " record: wrong number of fields");
  }
  long index(std::string_view s, long limit) {
    const int64_t v = I(s);
    if (v < 0 || v >= limit) reject("index " + std::string(s) + " out of range");
    return long(v);
  }
  // y ⊆ int [lo, hi] (strict) or y ⊆ [lo, hi], comparing the MPFI ends with exact doubles.
  static bool inside(const Ival& y, double lo, double hi, bool strict) {
    const int a = mpfr_cmp_d(y.L(), lo);
    const int b = mpfr_cmp_d(y.R(), hi);
    if (strict) return a > 0 && b < 0;
    return a >= 0 && b <= 0;
  }
  bool refutes(const Box& box) {
    pr->load(box.data());
    return pr->refute();
  }

  // hi - lo >= 2π, proved: a periodic root cell then covers every angle (a shorter one,
  // declared with a rounded pi, would leave a gap that splits an aspect at the seam).
  bool spans_period(double lo, double hi) {
    Ival w;
    mpfi_set_d(w, hi);
    mpfi_sub_d(w, w, lo);
    return mpfr_cmp(w.L(), ev->two_pi.R()) >= 0;
  }
  // A non-periodic variable v of `box` meets the inner enclosure of its declared domain,
  // so the box holds configurations of that domain (a periodic one always does, mod 2π).
  bool meets_domain(const double* box, int v) const {
    if (periodic[v]) return true;
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

  void header();
  long read_model();
  void load_model(const std::string& text, long model_rec, int64_t prec);
  void read_bounds(long model_rec);
  void read_domain();
  Factor read_factor();
  void require_triangular(Factor::Kind kind, const std::string& name);
  void tree();
  void end_tree(const Fields& f, const Stack& stack);
  void contraction(const Fields& f, Box& cell);
  void outcome(const Fields& f, Box& cell, Stack& stack);
  void bisection(const Fields& f, Box& cell, Stack& stack);
  void discard(const Fields& f, const Box& cell);
  void output_leaf(const Fields& f, const Box& cell);
  bool signs_ok(std::string_view s) const;
  void store(std::string_view signs, bool jac, const double* box, bool solution);
  void solution_leaf(const Fields& f, const Box& cell);
  Box solution_box(const Box& cell, const Box& Q, const Box& img);
  void unique_zero(const std::string& claim, const Box& Q, const std::vector<double>& C,
                   const Box& target, const std::string& outside);
  void link_section(UnionFind& uf);
  std::pair<long, long> link(const Fields& f, std::pair<long, long> prev);
  Box inner_intersection(long a, long b, std::string_view shift);
  std::vector<int64_t> csnc_section(UnionFind& uf);
  void cuspidal_section(const Fields& head);
  void run(const CheckOptions& o, Verdict& out);
};

void Checker::header() {
  const Fields& f = rd.next();
  if (f.size() != 2 || f[0] != "aspects-certificate")
    malformed(rec(), "not an aspects certificate");
  if (f[1] == "1") {
    version = 1;
  } else if (f[1] == "2") {
    version = 2;
  } else {
    malformed(rec(), "unknown certificate version '" + std::string(f[1]) + "'");
  }
  rd.expect({"tool", "aspects"}, 1);  // the writer's version: free text (FORMAT.md)
  read_bounds(read_model());
  read_domain();
  const int64_t count = I(rd.expect({"factors"}, 1)[1]);
  if (count < 0 || count > 20) reject("number of factors out of range 0..20");
  p = int(count);
  for (int i = 0; i < p; ++i) factors.push_back(read_factor());
  rd.expect({"tree"}, 0);
  R.nv = nv;
  R.p = p;
}

// The model record, its text and the precision; returns the model record's number.
long Checker::read_model() {
  const Fields& f = rd.expect({"model"}, 2);
  const long model_rec = rec();
  const int64_t bytes = I(f[1]);
  const std::string sha(f[2]);
  if (bytes < 0 || bytes > (1 << 20)) malformed(rec(), "model size out of range");
  if (sha.size() != 64 || sha.find_first_not_of("0123456789abcdef") != std::string::npos)
    malformed(rec(), "bad SHA-256 field");
  const std::string text = rd.raw(size_t(bytes));
  rd.expect({"end-model"}, 0);
  model_sha = sha256_hex(text);
  if (model_sha != sha) rejected(model_rec, "SHA-256 of the embedded model does not match");
  const int64_t prec = I(rd.expect({"precision"}, 1)[1]);
  if (prec < 24 || prec > 4096) malformed(rec(), "precision out of range 24..4096");
  mpfr_set_default_prec(mpfr_prec_t(prec));
  load_model(text, model_rec, prec);
  return model_rec;
}

void Checker::load_model(const std::string& text, long model_rec, int64_t prec) {
  try {
    m = parse_model(text);
    // A limit of the checker, not of the format: the evaluator keeps about nodes·(variables
    // + 5) intervals of `prec` bits (and MPFR aborts when out of memory).
    const double nodes = double(m.nodes.size());
    const double size = nodes * double(m.vars.size() + 5) * double(prec / 64 + 2);
    if (size > double(1 << 22))
      rejected(model_rec, "the embedded model is too large for the checker at this precision");
    ev.reset(new Evaluator(m));
  } catch (const ModelError& e) {
    malformed(model_rec, std::string("embedded model: ") + e.what());
  }
  pr.reset(new Prover(*ev));
  n = m.n();
  nv = int(m.vars.size());
}

// The declared domain of every variable, enclosed at the certificate's precision.
void Checker::read_bounds(long model_rec) {
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
    // at 24 bits (and a longer decimal at any precision), leaves a gap at the seam, and then
    // boxes holding no configuration of the declared domain count for the bound.
    if (x.periodic && !exactly_one_period(m, x))
      malformed(model_rec, what + "periodic domain of '" + x.name +
                               "' is not one period (exactly: a*pi + b, rational a, b)");
    periodic.push_back(x.periodic);
  }
}

// tau and eps (range only: informational) and the root cell.
void Checker::read_domain() {
  // One call per statement: the order in which a call's arguments are evaluated is
  // unspecified, and rec() must be read after expect() has moved to the record.
  const Fields& tau_record = rd.expect({"tau"}, 1);
  const double tau = parse_real(tau_record[1], rec());
  if (!(tau >= 1)) malformed(rec(), "tau must be >= 1");
  const Fields& eps_record = rd.expect({"eps"}, 1);
  const double eps = parse_real(eps_record[1], rec());
  if (!(eps > 0)) malformed(rec(), "eps must be > 0");
  const Fields& domain = rd.expect({"domain"}, 2 * size_t(nv));
  root = RealCursor(domain, 1, rec()).intervals(nv);
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

Factor Checker::read_factor() {
  const Fields& f = rd.next();
  const std::string k(f.size() > 1 ? f[1] : std::string_view());
  const bool with_arg = k == "diagFx" || k == "diagFq" || k == "user";
  const size_t fields = with_arg ? 3 : 2;
  if (f[0] != "factor" || f.size() != fields) malformed(rec(), "expected 'factor KIND [ARG]'");
  Factor fa{factor_kind(k), 0};
  if (!with_arg && k != "detFx" && k != "detFq")
    malformed(rec(), "unknown factor kind '" + k + "'");
  if (with_arg) {
    const long entries = fa.kind == Factor::User ? long(m.factors.size()) : n;
    fa.arg = int(index(f[2], 1 + entries)) - 1;
  }
  if (fa.arg < 0) reject("factor indices are 1-based");
  if (fa.kind == Factor::User) user_factors = true;
  if (fa.kind == Factor::DiagFx || fa.kind == Factor::DiagFq) require_triangular(fa.kind, k);
  return fa;
}

// det = product of the diagonal needs every entry above, or every entry below, the diagonal
// to be structurally zero (equation r does not mention variable c).
void Checker::require_triangular(Factor::Kind kind, const std::string& name) {
  const std::vector<int>& cols = kind == Factor::DiagFx ? m.pose : m.command;
  bool upper_zero = true;
  bool lower_zero = true;
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      if (!(m.nodes[m.eqs[r]].dep >> cols[c] & 1)) continue;
      upper_zero = upper_zero && c <= r;
      lower_zero = lower_zero && c >= r;
    }
  }
  if (!upper_zero && !lower_zero) reject(name + ": the matrix is not structurally triangular");
}

// SIGNS: p characters from "+-0", or "." when there is no factor.
bool Checker::signs_ok(std::string_view s) const {
  if (p == 0) return s == ".";
  return s.size() == size_t(p) && s.find_first_not_of("+-0") == std::string::npos;
}

// Parses SIGNS, proves every claimed sign on pr->box, and stores the output box.
void Checker::store(std::string_view s, bool jac, const double* box, bool solution) {
  if (!signs_ok(s)) malformed(rec(), "bad SIGNS field '" + std::string(s) + "'");
  uint32_t pos = 0;
  uint32_t neg = 0;
  Ival val;
  for (int i = 0; i < p; ++i) {
    if (s[i] == '0') continue;
    const std::string which = "factor " + std::to_string(i + 1);
    if (!pr->factor(factors[i], jac, val)) reject(which + " is not defined on the box");
    // A proved non-user factor leaves the Jacobians of the box computed, for the next ones.
    if (factors[i].kind != Factor::User) jac = true;
    const int claimed = s[i] == '+' ? 1 : -1;
    if (val.sign() != claimed)
      reject("sign '" + std::string(1, s[i]) + "' of " + which + " not proved");
    if (claimed > 0) {
      pos |= 1u << i;
    } else {
      neg |= 1u << i;
    }
  }
  R.lohi.insert(R.lohi.end(), box, box + 2 * nv);
  R.pos.push_back(pos);
  R.neg.push_back(neg);
  R.solution.push_back(solution);
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
    // A non-periodic command must stay in its declared domain (inner enclosure of bounds).
    if (!periodic[v] && !within_domain(v, img[2 * j], img[2 * j + 1]))
      reject("IMAGE leaves the declared domain of " + m.vars[v].name);
    B[2 * v] = img[2 * j];
    B[2 * v + 1] = img[2 * j + 1];
  }
  // The box must hold configurations of the declared domain: its commands lie in it (just
  // above), each pose variable must meet it. A box outside it may not count for the bound.
  for (int v : m.pose)
    if (!meets_domain(B.data(), v))
      reject("solution box misses the declared domain of " + m.vars[v].name + show(B));
  return B;
}

// A Hansen–Sengupta step on pr->box proves `claim` (P1 or P3): its image H lies in int Q~
// (so f has a unique zero in Q~) and in `target` (one lo/hi pair per command).
void Checker::unique_zero(const std::string& claim, const Box& Q, const std::vector<double>& C,
                          const Box& target, const std::string& outside) {
  if (const char* why = pr->newton(Q.data(), C.data())) reject(claim + ": " + why);
  for (int j = 0; j < n; ++j) {
    const Ival& y = pr->y[j];
    if (!inside(y, Q[2 * j], Q[2 * j + 1], true))
      reject(claim + ": the Hansen-Sengupta image is not inside the interior of Q~");
    if (!inside(y, target[2 * j], target[2 * j + 1], false)) reject(claim + ": " + outside);
  }
}

void Checker::solution_leaf(const Fields& f, const Box& cell) {
  const size_t nn = size_t(n) * n;
  const size_t weights = version == 1 ? 0 : 2 * size_t(n);
  count(f, 3 + 4 * size_t(n) + 3 * nn + weights);
  RealCursor in(f, 3, rec());
  const Box Q = in.intervals(n);
  const Box img = in.intervals(n);
  const std::vector<double> C = in.reals(nn);
  const std::vector<double> CX = in.reals(nn);
  const std::vector<double> CQ = in.reals(nn);
  std::vector<double> DX(n, 1.0);  // version 1: unscaled dominance
  std::vector<double> DQ(n, 1.0);
  if (version == 2) {
    DX = in.reals(n);
    DQ = in.reals(n);
  }
  for (int j = 0; j < n; ++j)
    if (!(DX[j] > 0) || !(DQ[j] > 0)) reject("P2: a column weight is not positive");
  const Box B = solution_box(cell, Q, img);
  pr->load(cell.data());
  unique_zero("P1", Q, C, img, "the Hansen-Sengupta image is not inside IMAGE");
  pr->load(B.data());
  const char* why = pr->regular(CX.data(), CQ.data(), DX.data(), DQ.data());
  if (why) reject(std::string("P2: ") + why);
  if (ev->feasible(pr->box.data()) != 2)
    reject("inner test: a constraint is not True on the box" + show(B));
  store(f[2], true, B.data(), true);
  ++solutions;
}

void Checker::tree() {
  Stack stack{root};  // depth-first preorder, left child on top
  for (;;) {
    Fields f = rd.next();
    budget();
    if (f[0] == "end-tree") {
      end_tree(f, stack);
      return;
    }
    if (stack.empty()) malformed(rec(), "expected 'end-tree': the search tree is complete");
    Box cell = std::move(stack.back());
    stack.pop_back();
    while (f[0] == "P") {
      contraction(f, cell);
      f = rd.next();
      budget();
    }
    outcome(f, cell, stack);
  }
}

void Checker::end_tree(const Fields& f, const Stack& stack) {
  count(f, 2);
  if (!stack.empty())
    reject("the search tree leaves " + std::to_string(stack.size()) + " cell(s) uncovered");
  if (I(f[1]) != int64_t(R.size())) reject("end-tree: wrong number of leaves");
}

// P: refutes both closed slabs outside [LO, HI], then narrows the cell to it.
void Checker::contraction(const Fields& f, Box& cell) {
  count(f, 4);
  const long v = index(f[1], nv);
  const Box lh = RealCursor(f, 2, rec()).intervals(1);
  const double lo = cell[2 * v];
  const double hi = cell[2 * v + 1];
  if (!within(lo, hi, lh[0], lh[1])) reject("contraction is not inside the cell");
  Box slab = cell;
  slab[2 * v + 1] = lh[0];
  if (lh[0] > lo && !refutes(slab))
    reject("cannot refute the slab below the contraction" + show(slab));
  slab[2 * v] = lh[1];
  slab[2 * v + 1] = hi;
  if (lh[1] < hi && !refutes(slab))
    reject("cannot refute the slab above the contraction" + show(slab));
  cell[2 * v] = lh[0];
  cell[2 * v + 1] = lh[1];
}

void Checker::outcome(const Fields& f, Box& cell, Stack& stack) {
  const std::string k(f[0]);
  if (k == "B") {
    bisection(f, cell, stack);
  } else if (k == "X") {
    discard(f, cell);
  } else if (k == "U" || k == "S" || k == "N") {
    output_leaf(f, cell);
  } else if (k == "end-tree") {
    malformed(rec(), "node without an outcome record");
  } else {
    malformed(rec(), "unknown record type '" + k + "'");
  }
}

void Checker::bisection(const Fields& f, Box& cell, Stack& stack) {
  count(f, 3);
  const long v = index(f[1], nv);
  const double x = parse_real(f[2], rec());
  if (!(cell[2 * v] < x && x < cell[2 * v + 1]))
    reject("bisection point not strictly inside the cell");
  stack.push_back(cell);
  stack.back()[2 * v] = x;  // right child below, left child on top
  cell[2 * v + 1] = x;
  stack.push_back(std::move(cell));
}

// X: the cell holds no feasible solution. The checker runs its whole refutation procedure
// whatever the hint says, so the hint is a label: checked for its form (hs, eq<i>, c<k>,
// canonical indices), never interpreted (FORMAT.md, "X <HINT>").
void Checker::discard(const Fields& f, const Box& cell) {
  count(f, 2);
  const std::string_view h = f[1];
  const size_t d = hint_prefix(h);
  const bool indexed = d > 0 && h.size() > d;
  if (h != "hs" && (!indexed || I(h.substr(d)) < 0))
    malformed(rec(), "bad hint '" + std::string(h) + "'");
  if (!refutes(cell)) reject("cannot refute the discarded cell" + show(cell));
}

void Checker::output_leaf(const Fields& f, const Box& cell) {
  const std::string k(f[0]);
  if (f.size() < 3) malformed(rec(), k + " record: too few fields");
  if (I(f[1]) != int64_t(R.size())) reject("output box ids must be 0, 1, 2, ... in order");
  if (k == "S") {
    solution_leaf(f, cell);
    return;
  }
  count(f, 3);
  pr->load(cell.data());
  // N (a cell a stopped search never reached) is checked and used as U is: its box is the
  // cell, it may hold solutions, and the bound counts it in every compatible class.
  store(f[2], false, cell.data(), false);
  ++(k == "N" ? unexplored : undecided);
}

void Checker::link_section(UnionFind& uf) {
  const int64_t total = I(rd.expect({"links"}, 1)[1]);
  if (total < 0) malformed(rec(), "negative count");
  std::pair<long, long> last(-1, -1);
  for (int64_t e = 0; e < total; ++e) {
    const Fields& f = rd.next();
    budget();
    if (f[0] != "K")
      malformed(rec(), "expected a K record (" + std::to_string(total) + " links announced)");
    last = link(f, last);
    uf.unite(int(last.first), int(last.second));
    ++links;
  }
}

// K: box A and box B shifted by 2πk share a solution (P3). `prev` is the previous link's
// (A, B): records are sorted and unique. Returns this link's (A, B).
std::pair<long, long> Checker::link(const Fields& f, std::pair<long, long> prev) {
  count(f, 4 + 3 * size_t(n) + size_t(n) * n);
  const long N = long(R.size());
  const long a = index(f[1], N);
  const long b = index(f[2], N);
  if (!(a < b)) reject("link needs A < B");
  if (!R.solution[a] || !R.solution[b])
    reject("link between boxes that are not both solution boxes");
  if (std::make_pair(a, b) <= prev) reject("links not sorted by (A, B) or repeated");
  const std::string_view sh = f[3];
  if (sh.size() != size_t(nv) || sh.find_first_not_of("-0+") != std::string::npos)
    malformed(rec(), "bad SHIFT field");
  RealCursor in(f, 4, rec());
  const std::vector<double> w = in.reals(n);
  const Box Q = in.intervals(n);
  const std::vector<double> C = in.reals(size_t(n) * n);
  const Box inner = inner_intersection(a, b, sh);
  Box X = inner;  // the witness pose, with the intersection's commands
  Box commands(2 * n);
  for (int j = 0; j < n; ++j) {
    const int v = m.pose[j];
    if (!within(inner[2 * v], inner[2 * v + 1], w[j], w[j]))
      reject("witness outside the boxes' intersection");
    X[2 * v] = w[j];
    X[2 * v + 1] = w[j];
    commands[2 * j] = inner[2 * m.command[j]];
    commands[2 * j + 1] = inner[2 * m.command[j] + 1];
  }
  pr->load(X.data());
  unique_zero("P3", Q, C, commands, "the command is not in both boxes");
  return {a, b};
}

// Box a ∩ (box b + 2πk), the shifted ends of b rounded inward (FORMAT.md, "Certified links").
Box Checker::inner_intersection(long a, long b, std::string_view shift) {
  Box inner(2 * nv);
  Ival t;
  for (int v = 0; v < nv; ++v) {
    const int k = shift_of(shift[v]);
    if (k && !periodic[v]) reject("shift on a non-periodic variable");
    double blo = R.box(b)[2 * v];
    double bhi = R.box(b)[2 * v + 1];
    if (k) {
      shift_by_periods(t, ev->two_pi, k, blo);
      blo = t.hi();
      shift_by_periods(t, ev->two_pi, k, bhi);
      bhi = t.lo();
    }
    inner[2 * v] = std::max(R.box(a)[2 * v], blo);
    inner[2 * v + 1] = std::min(R.box(a)[2 * v + 1], bhi);
    if (!(inner[2 * v] <= inner[2 * v + 1])) reject("the linked boxes do not meet");
  }
  return inner;
}

// The csnc records: each component is connected by verified links. Returns their sizes.
std::vector<int64_t> Checker::csnc_section(UnionFind& uf) {
  const int64_t comps = I(rd.expect({"csncs"}, 1)[1]);
  if (comps < 0) malformed(rec(), "negative count");
  std::vector<int64_t> sizes;
  csnc_of.assign(R.size(), -1);
  for (int64_t k = 0; k < comps; ++k) {
    const Fields& f = rd.next();
    if (f[0] != "csnc" || f.size() < 3) malformed(rec(), "expected a csnc record");
    if (I(f[1]) != k) reject("components must be numbered 0, 1, 2, ...");
    const int64_t size = I(f[2]);
    if (size < 1 || f.size() != 3 + size_t(size))
      malformed(rec(), "csnc: SIZE does not match the ids");
    if (!sizes.empty() && size > sizes.back()) reject("components not listed by decreasing size");
    sizes.push_back(size);
    long prev = -1;
    long first = -1;
    for (int64_t i = 0; i < size; ++i) {
      const long id = index(f[3 + i], long(R.size()));
      if (id <= prev) reject("component ids not increasing");
      if (!R.solution[id]) reject("component holds a box that is not a solution box");
      if (csnc_of[id] >= 0) reject("box " + std::to_string(id) + " is in two components");
      csnc_of[id] = int32_t(k);
      prev = id;
      if (i == 0) first = id;
      if (uf.find(int(id)) != uf.find(int(first)))
        reject("component is not connected by certified links");
    }
  }
  return sizes;
}

// The optional cuspidal section (FORMAT.md, "Cuspidality witnesses"): each W record names
// two solution boxes of one CSNC whose poses overlap and whose commands are disjoint.
void Checker::cuspidal_section(const Fields& head) {
  if (head.size() != 2) malformed(rec(), "expected 'cuspidal COUNT'");
  const int64_t total = I(head[1]);
  if (total < 0) malformed(rec(), "negative count");
  const WitnessVars vars{m.pose, m.command, periodic, ev->two_pi};
  long prev_c = -1;
  long prev_a = -1;
  long prev_b = -1;
  for (int64_t w = 0; w < total; ++w) {
    const Fields& f = rd.next();
    if (f[0] != "W")
      malformed(rec(), "expected a W record (" + std::to_string(total) + " witnesses announced)");
    count(f, 5);
    const long c = index(f[1], long(csncs_count));
    const long a = index(f[2], long(R.size()));
    const long b = index(f[3], long(R.size()));
    const std::string_view sh = f[4];
    if (sh.size() != size_t(nv) || sh.find_first_not_of("-0+") != std::string::npos)
      malformed(rec(), "bad SHIFT field");
    if (std::make_tuple(c, a, b) <= std::make_tuple(prev_c, prev_a, prev_b))
      reject("witnesses not sorted by (CSNC, A, B) or repeated");
    const WitnessCheck r = check_pose_witness(R, csnc_of, c, a, b, sh, vars);
    if (r != WitnessCheck::Verified) reject(witness_message(r));
    cuspidal_csncs += c != prev_c;
    prev_c = c;
    prev_a = a;
    prev_b = b;
    ++cuspidal;
  }
}

void Checker::run(const CheckOptions& o, Verdict& out) {
  const auto t0 = std::chrono::steady_clock::now();
  if (const char* e = std::getenv("CHECK_CERT_WORK_BASE"))
    work_base = std::max(10, std::min(40, std::atoi(e)));
  header();
  tree();
  UnionFind uf;
  uf.reset(R.size());
  link_section(uf);
  const std::vector<int64_t> sizes = csnc_section(uf);
  csncs_count = sizes.size();
  if (rd.next()[0] == "cuspidal") {
    cuspidal_section(rd.require({"cuspidal"}, 1));
    rd.next();
  }
  if (I(rd.require({"claim", "filtered"}, 1)[2]) != filtered_count(sizes))
    reject("claim filtered does not match the filtering rule");
  const int64_t claim = I(rd.expect({"claim", "lower-bound"}, 1)[2]);
  const long claim_rec = rec();
  if (claim < 0) malformed(rec(), "negative lower bound");
  const int64_t records = I(rd.expect({"end"}, 1)[1]);
  if (records != rec() - 1) malformed(rec(), "end: wrong record count");
  rd.expect_eof();
  // M may hold 2^22 + 64 per box pairs: a real subdivision has a few neighbours per box,
  // while S records that share one IMAGE over many cells make M quadratic (10^5 boxes:
  // 5·10^9 pairs, 40 GB) and would exhaust memory instead of being rejected.
  std::vector<std::pair<int, int>> M;
  try {
    M = neighbour_pairs(R, periodic, ev->two_pi, (size_t(1) << 22) + 64 * R.size());
  } catch (const std::length_error&) {
    rejected(claim_rec, "the neighbourhood graph has more than 2^22 + 64 pairs per box");
  }
  uint32_t all = 0;  // factor bits: every factor, the checkable ones
  uint32_t checkable = 0;
  for (int i = 0; i < p; ++i) {
    all |= 1u << i;
    if (factors[i].kind != Factor::User) checkable |= 1u << i;
  }
  long bound = 0;
  long checked = 0;
  try {
    bound = lower_bound(R, M, all);
    // Without the user factors, which the checker cannot verify, the bound may be lower.
    checked = user_factors ? lower_bound(R, M, checkable) : bound;
  } catch (const std::length_error&) {
    rejected(claim_rec, "too many sign classes for the neighbourhood graph (2^32 steps)");
  }
  if (claim > bound) {
    const std::string both = std::to_string(claim) + " exceeds the recomputed ";
    rejected(claim_rec, "claimed lower bound " + both + std::to_string(bound));
  }
  if (!o.quiet) {
    const auto elapsed = std::chrono::steady_clock::now() - t0;
    const double secs = std::chrono::duration<double>(elapsed).count();
    std::fprintf(stderr,
                 "check_cert: %ld refutations (%ld boxes), %llu node evaluations, %zu pairs in M, "
                 "recomputed lower bound %ld, %.2f s\n",
                 pr->refutations, pr->refute_boxes, (unsigned long long)ev->work, M.size(), bound,
                 secs);
  }
  out.verdict = "VERIFIED";
  if (claim > checked) {
    out.reason = "the claimed lower bound rests on user-supplied factors, which the checker "
                 "cannot verify; without them it is " + std::to_string(checked);
    if (o.trust_factors) {
      out.reason += "; trusted (--trust-factors)";
    } else {
      out.verdict = "UNCHECKED";
    }
  }
  out.cert_sha = rd.file_sha256();
  out.model_sha = model_sha;
  out.robot = m.name;
  out.solutions = solutions;
  out.undecided = undecided;
  out.unexplored = unexplored;
  out.links = links;
  out.csncs = long(sizes.size());
  out.cuspidal = cuspidal;
  out.cuspidal_csncs = cuspidal_csncs;
  out.claimed = claim;
  out.recomputed = bound;
  out.checked = checked;
  out.user_factors = user_factors;
}

}  // namespace

int cc::check_certificate(FILE* f, const CheckOptions& o, Verdict& out) {
  out = Verdict();
  std::unique_ptr<Checker> c;
  try {
    c.reset(new Checker(f));
    c->run(o, out);
    return out.verdict == "VERIFIED" ? kVerified : kUserFactors;
  } catch (const WorkLimit& e) {  // a limit of the checker: rejected, as out of memory
    out.verdict = "REJECTED";
    out.record = c ? c->rec() : 0;
    out.reason = e.what();
    return kRejected;
  } catch (const CertError& e) {
    out.verdict = e.malformed ? "MALFORMED" : "REJECTED";
    out.record = e.record;
    out.reason = e.what();
    return e.malformed ? kMalformed : kRejected;
  } catch (const std::bad_alloc&) {
    out.verdict = "REJECTED";
    out.reason = "out of memory";
  } catch (const std::exception& e) {
    out.verdict = "REJECTED";
    out.reason = std::string("internal error: ") + e.what();
  }
  return kRejected;
}

#ifndef CHECK_CERT_NO_MAIN
#include "aspects_version.h"  // generated by the build (version and git commit)
namespace {

// s as a JSON string literal: a name from the model cannot break out of its quotes.
std::string quoted(const std::string& s) {
  std::string q = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      q += '\\';
      q += char(c);
    } else if (c < 0x20 || c >= 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      q += buf;
    } else {
      q += char(c);
    }
  }
  return q + "\"";
}

// The counts of a verdict, in print order; the text line leaves out the recomputed bound.
struct Count {
  const char* name;
  long value;
  bool in_text;
};
std::vector<Count> counts(const Verdict& v) {
  return {{"solutions", v.solutions, true},
          {"undecided", v.undecided, true},
          {"unexplored", v.unexplored, true},
          {"links", v.links, true},
          {"csncs", v.csncs, true},
          {"cuspidal", v.cuspidal, true},
          {"cuspidal_csncs", v.cuspidal_csncs, true},
          {"lower_bound", v.claimed, true},
          {"recomputed_lower_bound", v.recomputed, false},
          {"checked_lower_bound", v.checked, true}};
}

// One line. The robot's name, the one field a user controls, comes last and quoted.
std::string text_line(const Verdict& v) {
  std::string s = "check_cert: " + v.verdict;
  if (v.verdict == "REJECTED" || v.verdict == "MALFORMED") {
    if (v.record > 0) s += " record " + std::to_string(v.record);
    return s + ": " + v.reason;
  }
  s += " sha256(cert)=" + v.cert_sha + " sha256(model)=" + v.model_sha;
  s += v.unexplored ? " complete=no" : " complete=yes";  // no: a stopped run's certificate
  for (const Count& c : counts(v))
    if (c.in_text) s += std::string(" ") + c.name + "=" + std::to_string(c.value);
  s += " robot=" + quoted(v.robot);
  if (!v.reason.empty()) s += " (" + v.reason + ")";
  return s;
}

std::string json_line(const Verdict& v, int code) {
  std::string s = "{\"verdict\": " + quoted(v.verdict);
  s += ", \"exit\": " + std::to_string(code);
  if (v.record > 0) s += ", \"record\": " + std::to_string(v.record);
  if (!v.reason.empty()) s += ", \"reason\": " + quoted(v.reason);
  if (code == kVerified || code == kUserFactors) {
    s += ", \"sha256_cert\": " + quoted(v.cert_sha);
    s += ", \"sha256_model\": " + quoted(v.model_sha);
    s += ", \"robot\": " + quoted(v.robot);
    s += std::string(", \"complete\": ") + (v.unexplored ? "false" : "true");
    for (const Count& c : counts(v))
      s += std::string(", \"") + c.name + "\": " + std::to_string(c.value);
    s += std::string(", \"user_factors\": ") + (v.user_factors ? "true" : "false");
  }
  return s + "}";
}

const char* const kHelp =
    "usage: check_cert [--quiet] [--json] [--trust-factors] FILE.cert | --version | --help\n"
    "Re-verifies a certificate of `aspects solve` (certificates/FORMAT.md).\n"
    "  --json           print the verdict as one JSON object (for scripts)\n"
    "  --trust-factors  accept a lower bound that rests on user-supplied factors\n"
    "Exit 0: verified; 1: rejected (or out of memory); 2: malformed or usage error;\n"
    "3: every proof verified, but the claimed lower bound rests on a user-supplied\n"
    "   `factor` the checker cannot verify (not given --trust-factors).\n";

}  // namespace

int main(int argc, char** argv) {
  CheckOptions o;
  bool json = false;
  bool usage = argc < 2;
  std::string path;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--help") {
      std::printf("%s", kHelp);
      return 0;
    }
    if (a == "--version") {  // like --help: prints and exits 0 wherever it stands
      std::printf("check_cert %s%s%s%s\n", ASPECTS_VERSION, *ASPECTS_GIT_COMMIT ? " (git " : "",
                  ASPECTS_GIT_COMMIT, *ASPECTS_GIT_COMMIT ? ")" : "");
      return 0;
    }
    if (a == "--quiet") {
      o.quiet = true;
    } else if (a == "--json") {
      json = true;
    } else if (a == "--trust-factors") {
      o.trust_factors = true;
    } else if (a.empty() || a[0] == '-' || !path.empty()) {
      usage = true;
    } else {
      path = a;
    }
  }
  if (usage || path.empty()) {
    std::fprintf(stderr, "usage: check_cert [--quiet] [--json] [--trust-factors] FILE.cert"
                         " (see --help)\n");
    return kMalformed;
  }
  FILE* f = std::fopen(path.c_str(), "rb");
  Verdict v;
  int code = kMalformed;
  if (f) {
    code = check_certificate(f, o, v);
  } else {
    v.verdict = "MALFORMED";
    v.reason = "cannot open " + path;
  }
  std::printf("%s\n", json ? json_line(v, code).c_str() : text_line(v).c_str());
  return code;
}
#endif
