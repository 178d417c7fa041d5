// check.h — trusted core: the state of one check and its record rules, shared by
// check.cpp (the header records, the claims, the whole run), tree.cpp (the search tree and
// its leaves), sections.cpp (links, CSNCs, witnesses) and count_check.h (a count
// certificate's records after its tree). It keeps only what later
// sections need: the output boxes as doubles with their claimed signs (each proved), the
// union-find of the links and the CSNC of each box.
#pragma once

#include <memory>
#include <tuple>

#include "speed.h"

namespace cc {

using Box = std::vector<double>;  // lo/hi pairs, one per variable (or per command)

// Variable (or command) i of box b := [lo, hi].
inline void put(Box& b, int i, double lo, double hi) {
  b[2 * i] = lo;
  b[2 * i + 1] = hi;
}

// lo <= a and b <= hi: [a, b] inside [lo, hi], on exact doubles.
inline bool within(double lo, double hi, double a, double b) { return lo <= a && b <= hi; }

// y ⊆ int [lo, hi] (strict) or y ⊆ [lo, hi], comparing the exact ends with exact doubles.
inline bool inside(const Ival& y, double lo, double hi, bool strict) {
  const int a = cmp(y, Lo, lo);
  const int b = cmp(y, Hi, hi);
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
  int version = 0;  // 1: P2 without column weights (D = 1); 2: with DX, DQ; 3: binary records
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
  bool speed = true;  // the speed layer (off with --trusted-only)
  size_t pairs_ = 0;  // pairs of M, for the statistics
  double graph_seconds_ = 0;  // building and sweeping M, for the statistics
  double tree_seconds_ = 0;   // the tree section: its records and their proofs, likewise
  // Last, so that it is destroyed first: its helper threads finish the proofs they hold
  // (which read the members above) before anything they read is gone, whatever was thrown.
  std::unique_ptr<ProofBatch> batch;

  Checker(FILE* f, Verdict& v) : rd(f), out(v) {}
  long rec() const { return rd.record(); }
  [[noreturn]] void reject(const std::string& why) { rejected(rec(), why); }
  // k intervals: in a binary record each end coded against the same end of `ref`'s
  // interval (FORMAT.md, "Format 3"); in a text record, as written.
  Box intervals(const double* ref, size_t k, int bits = kGridBits) {
    if (!rd.binary()) return rd.intervals(k);
    Box out(2 * k);
    for (size_t j = 0; j < 2 * k; ++j)
      out[j] = rd.end(ref[j & ~size_t(1)], ref[j | 1], j & 1, 0, bits);
    for (size_t j = 0; j < k; ++j)
      if (!(out[2 * j] <= out[2 * j + 1])) malformed(rec(), "interval with LO > HI");
    return out;
  }
  // The commands' lo/hi pairs of a box (command order).
  Box commands_of(const double* box) const {
    Box c(2 * n);
    for (int j = 0; j < n; ++j) put(c, j, box[2 * m.command[j]], box[2 * m.command[j] + 1]);
    return c;
  }
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
    Ival w, l;
    w.set(hi, hi);
    l.set(lo, lo);
    sub(w, w, l);
    return !less(w, Lo, ev->two_pi, Hi);
  }
  // Variable v of `box` meets the inner enclosure of its declared domain.
  bool meets_domain(const double* box, int v) const {
    const bool lo_below = cmp(dlo[v], Hi, box[2 * v + 1]) <= 0;
    return lo_below && cmp(dhi[v], Lo, box[2 * v]) >= 0;
  }
  // [lo, hi] lies in the inner enclosure of the declared domain of v.
  bool within_domain(int v, double lo, double hi) const {
    return cmp(dlo[v], Hi, lo) <= 0 && cmp(dhi[v], Lo, hi) >= 0;
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

  // The header records and the claims (check.cpp).
  void header();
  void read_model();
  void read_bounds(long model_rec);
  void read_domain();
  Factor read_factor();
  void require_triangular(Factor::Kind kind, std::string_view name);
  size_t claims(const CheckOptions& o);
  void run(const CheckOptions& o);
  void body(const CheckOptions& o);
  // The search tree and its leaves (tree.cpp).
  void tree();
  void contraction(Box& cell);
  void bisection(Box& cell, std::vector<Box>& stack);
  void discard(const Box& cell);
  void leaf(const Box& cell);
  bool at_most_eps(const Box& cell) const;
  void solution_leaf(const Box& cell);
  Box solution_box(const Box& cell, const Box& Q, const Box& img);
  std::string unique_zero(Prover& pr, const std::string& claim, const Box& Q,
                          const std::vector<double>& C, const Box& target,
                          const std::string& outside, bool pose = false) const;
  bool well_formed(std::string_view s) const;
  void store(std::string_view s, const double* box, bool solution);
  std::string signs_proved(Prover& pr, const std::string& s, bool jac) const;
  // A count certificate (count_check.cpp): its records after the tree, and its claims.
  bool count = false;
  void count_body();
  // The sections after the tree: links, CSNCs, witnesses (sections.cpp).
  std::vector<int> shifts();
  std::pair<double, double> inner(long a, long b, int v, int k);
  void link();
  void csnc(int64_t k);
  std::tuple<long, long, long> pair_in_csnc(bool w, const std::tuple<long, long, long>& last,
                                           std::vector<int>& k);
  void witness();
  void assembly();
  bool apart(long a, long b, int v);
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
};

}  // namespace cc
