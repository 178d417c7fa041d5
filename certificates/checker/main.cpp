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
#include <new>

#include "cert_reader.h"
#include "graph.h"
#include "proofs.h"

using namespace cc;

namespace {

using Fields = std::vector<std::string_view>;

struct Checker {
  LineReader rd;
  Model m;
  std::unique_ptr<Evaluator> ev;
  std::unique_ptr<Prover> pr;
  int n = 0, nv = 0, p = 0;
  int version = 0;             // 1: P2 without column weights (D = 1); 2: with DX, DQ
  std::vector<Ival> dlo, dhi;  // enclosures of the declared bounds
  std::vector<bool> periodic;
  std::vector<Factor> factors;
  bool user_factors = false;
  OutBoxes R;
  std::vector<double> root;  // the root cell (domain record)
  std::string model_sha;
  long solutions = 0, undecided = 0, links = 0;

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
    ev->work_limit = ((uint64_t(1) << work_base) + (uint64_t(1) << 10) * rd.bytes()) / weight;
  }
  int work_base = 29;
  [[noreturn]] void reject(const std::string& why) { rejected(rec(), why); }
  int64_t I(std::string_view s) { return parse_int(s, rec()); }
  void count(const Fields& f, size_t k) {
    if (f.size() != k) malformed(rec(), std::string(f[0]) + " record: wrong number of fields");
  }
  // f[i..i+k) as reals; consecutive pairs are intervals (LO <= HI) when `intervals`.
  std::vector<double> reals(const Fields& f, size_t i, size_t k, bool intervals = false) {
    std::vector<double> out(k);
    for (size_t j = 0; j < k; ++j) out[j] = parse_real(f[i + j], rec());
    for (size_t j = 0; intervals && j + 1 < k; j += 2)
      if (!(out[j] <= out[j + 1])) malformed(rec(), "interval with LO > HI");
    return out;
  }
  long index(std::string_view s, long limit) {
    int64_t v = I(s);
    if (v < 0 || v >= limit) reject("index " + std::string(s) + " out of range");
    return long(v);
  }
  // y ⊆ int [lo, hi] (strict) or y ⊆ [lo, hi], comparing the MPFI ends with exact doubles.
  static bool inside(const Ival& y, double lo, double hi, bool strict) {
    int a = mpfr_cmp_d(y.L(), lo), b = mpfr_cmp_d(y.R(), hi);
    return strict ? a > 0 && b < 0 : a >= 0 && b <= 0;
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
    return mpfr_cmp_d(dlo[v].R(), box[2 * v + 1]) <= 0 && mpfr_cmp_d(dhi[v].L(), box[2 * v]) >= 0;
  }

  std::string show(const std::vector<double>& b) const {  // a box, for messages
    std::string s;
    char buf[64];
    for (int v = 0; v < nv; ++v)
      std::snprintf(buf, sizeof buf, "%s%s in [%.17g, %.17g]", v ? ", " : " (", m.vars[v].name.c_str(), b[2 * v], b[2 * v + 1]), s += buf;
    return s + ")";
  }

  void header();
  void tree();
  void store(std::string_view signs, bool jac, const double* box, bool solution);
  void solution_leaf(const Fields& f, const std::vector<double>& cell);
  void link_section(UnionFind& uf);
  void run(const CheckOptions& o, Verdict& out);
};

void Checker::header() {
  const Fields* f = &rd.next();
  if (f->size() != 2 || (*f)[0] != "aspects-certificate") malformed(rec(), "not an aspects certificate");
  std::string_view v = (*f)[1];
  if (v != "1" && v != "2") malformed(rec(), "unknown certificate version '" + std::string(v) + "'");
  version = v == "1" ? 1 : 2;
  rd.expect({"tool", "aspects"}, 1);
  f = &rd.expect({"model"}, 2);
  long model_rec = rec();
  int64_t bytes = I((*f)[1]);
  std::string sha((*f)[2]);
  if (bytes < 0 || bytes > (1 << 20)) malformed(rec(), "model size out of range");
  if (sha.size() != 64 || sha.find_first_not_of("0123456789abcdef") != std::string::npos)
    malformed(rec(), "bad SHA-256 field");
  std::string text = rd.raw(size_t(bytes));
  rd.expect({"end-model"}, 0);
  model_sha = sha256_hex(text);
  if (model_sha != sha) rejected(model_rec, "SHA-256 of the embedded model does not match");
  int64_t prec = I(rd.expect({"precision"}, 1)[1]);
  if (prec < 24 || prec > 4096) malformed(rec(), "precision out of range 24..4096");
  mpfr_set_default_prec(mpfr_prec_t(prec));
  try {
    m = parse_model(text);
    // A limit of the checker, not of the format: the evaluator keeps about nodes·(variables
    // + 5) intervals of `prec` bits (and MPFR aborts when out of memory).
    if (double(m.nodes.size()) * double(m.vars.size() + 5) * double(prec / 64 + 2) > double(1 << 22))
      rejected(model_rec, "the embedded model is too large for the checker at this precision");
    ev.reset(new Evaluator(m));
  } catch (const ModelError& e) {
    malformed(model_rec, std::string("embedded model: ") + e.what());
  }
  pr.reset(new Prover(*ev));
  n = m.n(), nv = int(m.vars.size());
  dlo.resize(nv), dhi.resize(nv);
  for (int v = 0; v < nv; ++v) {
    const Var& x = m.vars[v];
    if (!ev->constant(x.lo, dlo[v]) || !ev->constant(x.hi, dhi[v]))
      malformed(model_rec, "embedded model: domain bound of '" + x.name + "' is not a finite number");
    if (mpfr_cmp(dlo[v].L(), dhi[v].R()) > 0 || mpfr_cmp(dlo[v].R(), dhi[v].L()) > 0)
      malformed(model_rec, "embedded model: empty or reversed domain of '" + x.name + "'");
    // Exactly, not by intervals: `[-3.1415926, 3.1415926] periodic` passes an interval test at
    // 24 bits (and a longer decimal at any precision), leaves a gap at the seam, and then
    // boxes holding no configuration of the declared domain count for the bound.
    if (x.periodic && !exactly_one_period(m, x))
      malformed(model_rec, "embedded model: periodic domain of '" + x.name +
                               "' is not one period (exactly: a*pi + b, rational a, b)");
    periodic.push_back(x.periodic);
  }
  if (!(parse_real(rd.expect({"tau"}, 1)[1], rec()) >= 1)) malformed(rec(), "tau must be >= 1");
  if (!(parse_real(rd.expect({"eps"}, 1)[1], rec()) > 0)) malformed(rec(), "eps must be > 0");
  root = reals(rd.expect({"domain"}, 2 * size_t(nv)), 1, 2 * nv, true);
  for (int v = 0; v < nv; ++v) {
    // The root cell is the declared domain rounded outward to doubles, nothing more: it
    // covers every configuration, and it cannot hold boxes of another (wider) domain.
    if (root[2 * v] != dlo[v].lo() || root[2 * v + 1] != dhi[v].hi())
      reject("root cell is not the declared domain of '" + m.vars[v].name +
             "' rounded outward to doubles");
    if (periodic[v] && !spans_period(root[2 * v], root[2 * v + 1]))
      reject("root cell of periodic '" + m.vars[v].name + "' does not provably span 2*pi");
  }
  int64_t pp = I(rd.expect({"factors"}, 1)[1]);
  if (pp < 0 || pp > 20) reject("number of factors out of range 0..20");
  p = int(pp);
  for (int i = 0; i < p; ++i) {
    f = &rd.next();
    const std::string k(f->size() > 1 ? (*f)[1] : std::string_view());
    bool with_arg = k == "diagFx" || k == "diagFq" || k == "user";
    if ((*f)[0] != "factor" || f->size() != (with_arg ? 3u : 2u)) malformed(rec(), "expected 'factor KIND [ARG]'");
    Factor fa{k == "detFx" ? Factor::DetFx : k == "detFq" ? Factor::DetFq : k == "diagFx" ? Factor::DiagFx
              : k == "diagFq" ? Factor::DiagFq : Factor::User, 0};
    if (!with_arg && k != "detFx" && k != "detFq") malformed(rec(), "unknown factor kind '" + k + "'");
    if (with_arg) fa.arg = int(index((*f)[2], 1 + (fa.kind == Factor::User ? long(m.factors.size()) : n))) - 1;
    if (fa.arg < 0) reject("factor indices are 1-based");
    user_factors |= fa.kind == Factor::User;
    if (fa.kind == Factor::DiagFx || fa.kind == Factor::DiagFq) {
      // det = product of the diagonal needs every entry above, or every entry below, the
      // diagonal to be structurally zero (equation r does not mention variable c).
      const std::vector<int>& cols = fa.kind == Factor::DiagFx ? m.pose : m.command;
      bool upper_zero = true, lower_zero = true;
      for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c)
          if (m.nodes[m.eqs[r]].dep >> cols[c] & 1) upper_zero &= c <= r, lower_zero &= c >= r;
      if (!upper_zero && !lower_zero) reject(k + ": the matrix is not structurally triangular");
    }
    factors.push_back(fa);
  }
  rd.expect({"tree"}, 0);
  R.nv = nv, R.p = p;
}

// Parses SIGNS, proves every claimed sign on pr->box, and stores the output box.
void Checker::store(std::string_view s, bool jac, const double* box, bool solution) {
  if (p == 0 ? s != "." : (s.size() != size_t(p) || s.find_first_not_of("+-0") != std::string::npos))
    malformed(rec(), "bad SIGNS field '" + std::string(s) + "'");
  uint32_t pos = 0, neg = 0;
  Ival val;
  for (int i = 0; i < p; ++i) {
    if (s[i] == '0') continue;
    if (!pr->factor(factors[i], jac, val)) reject("factor " + std::to_string(i + 1) + " is not defined on the box");
    jac |= factors[i].kind != Factor::User;
    if (val.sign() != (s[i] == '+' ? 1 : -1))
      reject("sign '" + std::string(1, s[i]) + "' of factor " + std::to_string(i + 1) + " not proved");
    (s[i] == '+' ? pos : neg) |= 1u << i;
  }
  R.lohi.insert(R.lohi.end(), box, box + 2 * nv);
  R.pos.push_back(pos), R.neg.push_back(neg), R.solution.push_back(solution);
}

void Checker::solution_leaf(const Fields& f, const std::vector<double>& cell) {
  const size_t nn = size_t(n) * n;
  const size_t weights = version == 1 ? 0 : 2 * size_t(n);
  count(f, 3 + 4 * size_t(n) + 3 * nn + weights);
  std::vector<double> Q = reals(f, 3, 2 * n, true), img = reals(f, 3 + 2 * n, 2 * n, true),
                      C = reals(f, 3 + 4 * n, nn), CX = reals(f, 3 + 4 * n + nn, nn),
                      CQ = reals(f, 3 + 4 * n + 2 * nn, nn);
  std::vector<double> DX(n, 1.0), DQ(n, 1.0);  // version 1: unscaled dominance
  if (version == 2) {
    DX = reals(f, 3 + 4 * n + 3 * nn, n);
    DQ = reals(f, 3 + 5 * n + 3 * nn, n);
  }
  for (int j = 0; j < n; ++j)
    if (!(DX[j] > 0) || !(DQ[j] > 0)) reject("P2: a column weight is not positive");
  std::vector<double> B = cell;  // the output box: the cell's poses, IMAGE's commands
  for (int j = 0; j < n; ++j) {
    int v = m.command[j];
    if (!(Q[2 * j] <= cell[2 * v] && cell[2 * v + 1] <= Q[2 * j + 1]))
      reject("coverage: the cell's " + m.vars[v].name + " is not inside Q~");
    if (!(Q[2 * j] <= img[2 * j] && img[2 * j + 1] <= Q[2 * j + 1])) reject("IMAGE is not inside Q~");
    // A non-periodic command must stay in its declared domain (inner enclosure of bounds).
    if (!periodic[v] && (mpfr_cmp_d(dlo[v].R(), img[2 * j]) > 0 || mpfr_cmp_d(dhi[v].L(), img[2 * j + 1]) < 0))
      reject("IMAGE leaves the declared domain of " + m.vars[v].name);
    B[2 * v] = img[2 * j], B[2 * v + 1] = img[2 * j + 1];
  }
  // The box must hold configurations of the declared domain: its commands lie in it (just
  // above), each pose variable must meet it. A box outside it may not count for the bound.
  for (int v : m.pose)
    if (!meets_domain(B.data(), v))
      reject("solution box misses the declared domain of " + m.vars[v].name + show(B));
  pr->load(cell.data());
  if (const char* why = pr->newton(Q.data(), C.data())) reject(std::string("P1: ") + why);
  for (int j = 0; j < n; ++j) {
    if (!inside(pr->y[j], Q[2 * j], Q[2 * j + 1], true)) reject("P1: the Hansen-Sengupta image is not inside the interior of Q~");
    if (!inside(pr->y[j], img[2 * j], img[2 * j + 1], false)) reject("P1: the Hansen-Sengupta image is not inside IMAGE");
  }
  pr->load(B.data());
  if (const char* why = pr->regular(CX.data(), CQ.data(), DX.data(), DQ.data())) reject(std::string("P2: ") + why);
  if (ev->feasible(pr->box.data()) != 2) reject("inner test: a constraint is not True on the box" + show(B));
  store(f[2], true, B.data(), true);
  ++solutions;
}

void Checker::tree() {
  std::vector<std::vector<double>> stack{root};  // depth-first preorder, left child on top
  for (;;) {
    Fields f = rd.next();
    budget();
    if (f[0] == "end-tree") {
      count(f, 2);
      if (!stack.empty()) reject("the search tree leaves " + std::to_string(stack.size()) + " cell(s) uncovered");
      if (I(f[1]) != int64_t(R.size())) reject("end-tree: wrong number of leaves");
      return;
    }
    if (stack.empty()) malformed(rec(), "expected 'end-tree': the search tree is complete");
    std::vector<double> cell = std::move(stack.back());
    stack.pop_back();
    for (; f[0] == "P"; f = rd.next(), budget()) {  // contractions: refute both closed slabs
      count(f, 4);
      long v = index(f[1], nv);
      std::vector<double> lh = reals(f, 2, 2, true), slab = cell;
      double lo = cell[2 * v], hi = cell[2 * v + 1];
      if (!(lo <= lh[0] && lh[1] <= hi)) reject("contraction is not inside the cell");
      slab[2 * v + 1] = lh[0];
      if (lh[0] > lo && (pr->load(slab.data()), !pr->refute())) reject("cannot refute the slab below the contraction" + show(slab));
      slab[2 * v] = lh[1], slab[2 * v + 1] = hi;
      if (lh[1] < hi && (pr->load(slab.data()), !pr->refute())) reject("cannot refute the slab above the contraction" + show(slab));
      cell[2 * v] = lh[0], cell[2 * v + 1] = lh[1];
    }
    const std::string k(f[0]);
    if (k == "B") {
      count(f, 3);
      long v = index(f[1], nv);
      double x = parse_real(f[2], rec());
      if (!(cell[2 * v] < x && x < cell[2 * v + 1])) reject("bisection point not strictly inside the cell");
      stack.push_back(cell);
      stack.back()[2 * v] = x;  // right child below, left child on top
      cell[2 * v + 1] = x;
      stack.push_back(std::move(cell));
    } else if (k == "X") {
      count(f, 2);
      std::string_view h = f[1];
      size_t d = h.compare(0, 2, "eq") == 0 ? 2 : h[0] == 'c';  // hs, eq<i> or c<k>
      if (h != "hs" && !(d && h.size() > d && I(h.substr(d)) >= 0)) malformed(rec(), "bad hint '" + std::string(h) + "'");
      pr->load(cell.data());
      if (!pr->refute()) reject("cannot refute the discarded cell" + show(cell));
    } else if (k == "U" || k == "S") {
      if (f.size() < 3) malformed(rec(), k + " record: too few fields");
      if (I(f[1]) != int64_t(R.size())) reject("output box ids must be 0, 1, 2, ... in order");
      if (k == "S") {
        solution_leaf(f, cell);
      } else {
        count(f, 3);
        pr->load(cell.data());
        store(f[2], false, cell.data(), false);
        ++undecided;
      }
    } else {
      malformed(rec(), k == "end-tree" ? "node without an outcome record" : "unknown record type '" + k + "'");
    }
  }
}

void Checker::link_section(UnionFind& uf) {
  int64_t total = I(rd.expect({"links"}, 1)[1]);
  if (total < 0) malformed(rec(), "negative count");
  const long N = long(R.size());
  long pa = -1, pb = -1;
  std::vector<double> I_(2 * nv);
  Ival t;
  for (int64_t e = 0; e < total; ++e) {
    const Fields& f = rd.next();
    budget();
    if (f[0] != "K") malformed(rec(), "expected a K record (" + std::to_string(total) + " links announced)");
    count(f, 4 + 3 * size_t(n) + size_t(n) * n);
    long a = index(f[1], N), b = index(f[2], N);
    if (!(a < b)) reject("link needs A < B");
    if (!R.solution[a] || !R.solution[b]) reject("link between boxes that are not both solution boxes");
    if (!(a > pa || (a == pa && b > pb))) reject("links not sorted by (A, B) or repeated");
    pa = a, pb = b;
    std::string_view sh = f[3];
    if (sh.size() != size_t(nv) || sh.find_first_not_of("-0+") != std::string::npos) malformed(rec(), "bad SHIFT field");
    std::vector<double> w = reals(f, 4, n), Q = reals(f, 4 + n, 2 * n, true), C = reals(f, 4 + 3 * n, size_t(n) * n);
    // Inner intersection of box a with box b shifted by 2πk (shifted ends rounded inward).
    for (int v = 0; v < nv; ++v) {
      int k = sh[v] == '+' ? 1 : sh[v] == '-' ? -1 : 0;
      if (k && !periodic[v]) reject("shift on a non-periodic variable");
      double blo = R.box(b)[2 * v], bhi = R.box(b)[2 * v + 1];
      if (k) {
        mpfi_mul_si(t, ev->two_pi, k);
        mpfi_add_d(t, t, R.box(b)[2 * v]);
        blo = t.hi();
        mpfi_mul_si(t, ev->two_pi, k);
        mpfi_add_d(t, t, R.box(b)[2 * v + 1]);
        bhi = t.lo();
      }
      I_[2 * v] = std::max(R.box(a)[2 * v], blo);
      I_[2 * v + 1] = std::min(R.box(a)[2 * v + 1], bhi);
      if (!(I_[2 * v] <= I_[2 * v + 1])) reject("the linked boxes do not meet");
    }
    std::vector<double> X = I_;
    for (int j = 0; j < n; ++j) {
      int v = m.pose[j];
      if (!(I_[2 * v] <= w[j] && w[j] <= I_[2 * v + 1])) reject("witness outside the boxes' intersection");
      X[2 * v] = X[2 * v + 1] = w[j];
    }
    pr->load(X.data());
    if (const char* why = pr->newton(Q.data(), C.data())) reject(std::string("P3: ") + why);
    for (int j = 0; j < n; ++j) {
      int v = m.command[j];
      if (!inside(pr->y[j], Q[2 * j], Q[2 * j + 1], true)) reject("P3: the Hansen-Sengupta image is not inside the interior of Q~");
      if (!inside(pr->y[j], I_[2 * v], I_[2 * v + 1], false)) reject("P3: the command is not in both boxes");
    }
    uf.unite(int(a), int(b));
    ++links;
  }
}

void Checker::run(const CheckOptions& o, Verdict& out) {
  auto t0 = std::chrono::steady_clock::now();
  if (const char* e = std::getenv("CHECK_CERT_WORK_BASE"))
    work_base = std::max(10, std::min(40, std::atoi(e)));
  header();
  tree();
  UnionFind uf;
  uf.reset(R.size());
  link_section(uf);
  int64_t comps = I(rd.expect({"csncs"}, 1)[1]);
  if (comps < 0) malformed(rec(), "negative count");
  std::vector<int64_t> sizes;
  std::vector<uint8_t> used(R.size(), 0);
  for (int64_t k = 0; k < comps; ++k) {
    const Fields& f = rd.next();
    if (f[0] != "csnc" || f.size() < 3) malformed(rec(), "expected a csnc record");
    if (I(f[1]) != k) reject("components must be numbered 0, 1, 2, ...");
    int64_t size = I(f[2]);
    if (size < 1 || f.size() != 3 + size_t(size)) malformed(rec(), "csnc: SIZE does not match the ids");
    if (!sizes.empty() && size > sizes.back()) reject("components not listed by decreasing size");
    sizes.push_back(size);
    long prev = -1, first = -1;
    for (int64_t i = 0; i < size; ++i) {
      long id = index(f[3 + i], long(R.size()));
      if (id <= prev) reject("component ids not increasing");
      if (!R.solution[id]) reject("component holds a box that is not a solution box");
      if (used[id]) reject("box " + std::to_string(id) + " is in two components");
      used[id] = 1, prev = id;
      if (first < 0) first = id;
      if (uf.find(int(id)) != uf.find(int(first))) reject("component is not connected by certified links");
    }
  }
  if (I(rd.expect({"claim", "filtered"}, 1)[2]) != filtered_count(sizes))
    reject("claim filtered does not match the filtering rule");
  int64_t claim = I(rd.expect({"claim", "lower-bound"}, 1)[2]);
  long claim_rec = rec();
  if (claim < 0) malformed(rec(), "negative lower bound");
  if (I(rd.expect({"end"}, 1)[1]) != rec() - 1) malformed(rec(), "end: wrong record count");
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
  uint32_t all = 0, checkable = 0;  // factor bits: every factor, the checkable ones
  for (int i = 0; i < p; ++i) {
    all |= 1u << i;
    if (factors[i].kind != Factor::User) checkable |= 1u << i;
  }
  long bound = 0, checked = 0;
  try {
    bound = lower_bound(R, M, all);
    // Without the user factors, which the checker cannot verify, the bound may be lower.
    checked = user_factors ? lower_bound(R, M, checkable) : bound;
  } catch (const std::length_error&) {
    rejected(claim_rec, "too many sign classes for the neighbourhood graph (2^32 steps)");
  }
  if (claim > bound)
    rejected(claim_rec, "claimed lower bound " + std::to_string(claim) + " exceeds the recomputed " + std::to_string(bound));
  if (!o.quiet)
    std::fprintf(stderr,
                 "check_cert: %ld refutations (%ld boxes), %llu node evaluations, %zu pairs in M, "
                 "recomputed lower bound %ld, %.2f s\n",
                 pr->refutations, pr->refute_boxes, (unsigned long long)ev->work, M.size(), bound,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  out.verdict = "VERIFIED";
  if (claim > checked) {
    out.reason = "the claimed lower bound rests on user-supplied factors, which the checker "
                 "cannot verify; without them it is " + std::to_string(checked);
    if (o.trust_factors) out.reason += "; trusted (--trust-factors)";
    else out.verdict = "UNCHECKED";
  }
  out.cert_sha = rd.file_sha256();
  out.model_sha = model_sha;
  out.robot = m.name;
  out.solutions = solutions;
  out.undecided = undecided;
  out.links = links;
  out.csncs = comps;
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

// One line. The robot's name, the one field a user controls, comes last and quoted.
std::string text_line(const Verdict& v) {
  std::string s = "check_cert: " + v.verdict;
  if (v.verdict == "REJECTED" || v.verdict == "MALFORMED") {
    if (v.record > 0) s += " record " + std::to_string(v.record);
    return s + ": " + v.reason;
  }
  s += " sha256(cert)=" + v.cert_sha + " sha256(model)=" + v.model_sha;
  s += " solutions=" + std::to_string(v.solutions);
  s += " undecided=" + std::to_string(v.undecided);
  s += " links=" + std::to_string(v.links);
  s += " csncs=" + std::to_string(v.csncs);
  s += " lower_bound=" + std::to_string(v.claimed);
  s += " checked_lower_bound=" + std::to_string(v.checked);
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
    s += ", \"solutions\": " + std::to_string(v.solutions);
    s += ", \"undecided\": " + std::to_string(v.undecided);
    s += ", \"links\": " + std::to_string(v.links);
    s += ", \"csncs\": " + std::to_string(v.csncs);
    s += ", \"lower_bound\": " + std::to_string(v.claimed);
    s += ", \"recomputed_lower_bound\": " + std::to_string(v.recomputed);
    s += ", \"checked_lower_bound\": " + std::to_string(v.checked);
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
