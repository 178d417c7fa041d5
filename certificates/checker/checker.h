// checker.h — every declaration of check_cert's trusted core, the independent checker of
// the certificates of `aspects solve` (FORMAT.md is the specification). It shares no code
// with core/ or proofs/. The trusted core, which alone decides a verdict under
// --trusted-only: the reader (cert_reader.cpp, compressed_input.cpp), the model parser
// (model.cpp), MPFI intervals (interval.cpp), the evaluator (eval.cpp), the proofs on one box
// (proofs.cpp), the record rules (check.h: check.cpp, tree.cpp, sections.cpp), the graph M
// with the bound (bound.cpp), and a count certificate's records (count_check.h: count_check.cpp,
// count_proofs.cpp, count_connected.cpp, with the Jacobian of f as DAG nodes for the second
// derivatives: derivative.cpp): MPFI, MPFR and GMP its only arithmetic. The optional speed
// layer, tested against the core: speed.h (proofs on T threads and P ranks, the strip
// sweep of M), intervals of doubles at 53 bits (interval_doubles.h/.cpp), and incremental
// evaluation and the ends of sin, cos, asin and acos from Arb (eval_speed.cpp). The command
// line and its output: cli.cpp.
#pragma once

#include <openssl/evp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "interval.h"

namespace cc {

// ---- The lexical layer (cert_reader.cpp, FORMAT.md "Lexical rules"): one record per line,
// single-space separated fields, canonical decimal integers and canonical `%a` hexadecimal
// reals; in format 3 also binary records (a first byte >= 0x80, FORMAT.md "Format 3"),
// decoded into the same fields, each end still coded against its reference interval. The
// reader hashes every byte it consumes (SHA-256 of the whole file) and numbers lines for
// error messages. Anything that does not follow the rules is a Malformed error
// (exit 2); failed verifications are Rejected errors (exit 1), thrown by the other modules
// with the record they concern.
struct CertError : std::runtime_error {
  bool malformed;  // true: exit 2; false: exit 1 (REJECTED)
  long record;
  CertError(bool m, long r, const std::string& why)
      : std::runtime_error(why), malformed(m), record(r) {}
};
[[noreturn]] void malformed(long record, const std::string& why);
[[noreturn]] void rejected(long record, const std::string& why);

std::string sha256_hex(const std::string& bytes);
// A canonical decimal integer (FORMAT.md); `rec` is the record named in the error.
int64_t parse_int(std::string_view s, long rec);
// A canonical hexadecimal real (FORMAT.md), exactly.
double parse_real(std::string_view s, long rec);

// f itself, or, if f holds a zstd stream (compressed_input.cpp), a stream of its
// decompressed bytes that owns f. A corrupt or truncated stream reads as a read error.
FILE* decompressed(FILE* f);

// Format 3's grids (FORMAT.md, "Format 3"): G of most coded ends, G of contraction ends,
// and the OFFSET of bisection points (the middle of the cell is code 0).
inline constexpr int kGridBits = 16, kContractionGridBits = 10;
inline constexpr int64_t kMiddleOffset = int64_t(1) << (kGridBits - 1);

class LineReader {
 public:
  explicit LineReader(FILE* f);  // takes ownership of f, and reads it through decompressed()
  ~LineReader();
  // Reads the next record and splits it into fields; checks the lexical rules.
  LineReader& next();
  // next(), then requires the leading fields == words and `extra` further fields.
  LineReader& expect(const std::vector<const char*>& words, size_t extra);
  // The same test on the record read last.
  LineReader& require(const std::vector<const char*>& words, size_t extra);
  void count(size_t k);  // the record read last has k fields (binary ones always do)
  std::string_view kind() const { return binary_ ? bin_kind_ : fields_[0]; }
  size_t size() const { return binary_ ? bin_.size() + 1 : fields_.size(); }
  // The fields of the record read last, left to right after its leading words.
  std::string_view word();
  int64_t integer();
  double real();
  std::vector<double> reals(size_t k);
  // k intervals LO HI (2k reals, all parsed before any LO <= HI is checked).
  std::vector<double> intervals(size_t k);
  // An end coded against [a, b] (format 3: fma(z, u, a or, if `upper`, b), u = (b − a)·2^-16,
  // z the code plus `offset`, or 8 bytes); in a text record, the next real.
  double end(double a, double b, bool upper, int64_t offset = 0, int bits = kGridBits);
  // Format 3: binary records may follow, their fields sized by n, nv and p.
  void allow_binary(int n, int nv, int p);
  bool binary() const { return binary_; }  // the record read last is binary
  // --print: every record as version 2 text on stdout, a binary one with the ends decoded
  // so far once the next is read (or finish_print() is called).
  void print(bool on) { print_ = on; }
  void finish_print();
  // Reads exactly `n` raw bytes (the embedded model text) and counts its lines.
  std::string raw(size_t n);
  void expect_eof();                         // nothing may follow the last record
  long record() const { return line_; }      // number of the record read last
  uint64_t bytes() const { return bytes_; }  // bytes read so far
  std::string file_sha256();                 // after expect_eof

 private:
  FILE* f_ = nullptr;
  EVP_MD_CTX* md_ = nullptr;
  char* line_buf_ = nullptr;
  size_t line_cap_ = 0;
  long line_ = 0;
  uint64_t bytes_ = 0;
  std::vector<std::string_view> fields_;  // views into line_buf_, valid until the next read
  size_t pos_ = 0;                        // the next field word() returns
  // Binary records (cert_reader.cpp): the decoded fields, each an integer, a word or a
  // coded end (raw: x is the end, as written or once end() decoded it; else z is its code).
  struct Field {
    enum Type : uint8_t { Int, Word, Code } type;
    bool raw = false;
    int64_t z = 0;
    double x = 0;
    uint32_t off = 0, len = 0;  // a word: words_[off, off + len)
  };
  bool allow_binary_ = false, binary_ = false, print_ = false, printed_ = false;
  std::string_view bin_kind_;
  int n_ = 0, nv_ = 0, p_ = 0;
  std::vector<Field> bin_;
  std::string words_, bytes_read_;  // the words of bin_; the record's bytes (for the hash)
  int64_t last_id_ = -1, last_a_ = 0;  // ids and link A are coded as steps
  int byte();
  uint64_t varint();
  void decode(int tag);
  void add(Field::Type t, int64_t i = 0);
  void code();
  void word(std::string w);
  const Field& field(Field::Type t);
};

// ---- The whole check (check.cpp): reads a certificate from f (closed on return) and says
// what it found; the outcome is the exit status.
struct CheckOptions {
  bool quiet = false;          // no statistics on stderr
  bool trust_factors = false;  // accept a bound that rests on user-supplied factors
  int threads = 0;             // threads for the interval proofs (0: one per core)
  bool trusted_only = false;   // no speed layer: proofs in line, the plain sweep of M
  bool print = false;          // every record as text on stdout (FORMAT.md, "Format 3")
};

// The outcome of a check; its value is check_cert's exit status.
enum class Outcome { Verified = 0, Rejected = 1, Malformed = 2, Unchecked = 3 };
const char* outcome_name(Outcome o);  // VERIFIED, REJECTED, MALFORMED, UNCHECKED

// What a check found.
struct Verdict {
  Outcome outcome = Outcome::Rejected;
  std::string reason, cert_sha, model_sha, robot;
  long record = 0;  // the record a rejection concerns
  long solutions = 0, undecided = 0, links = 0, csncs = 0;
  long unexplored = 0;  // N records: a stopped run's cells never searched (complete=no)
  long wide_undecided = 0;  // U records wider than eps, which the search rule never ends
  double eps = 0;           // the search's eps (eps record): complete is relative to it
  long cuspidal = 0, cuspidal_csncs = 0;  // verified W records; CSNCs with one
  long assembly = 0;                      // verified V records
  long claimed = -1, recomputed = -1, checked = -1;  // bounds: claimed, all factors, no user
  bool user_factors = false;
  long count_cells = -1;  // a count certificate (count_check.cpp): boxes of its final cover
  long count_upper = -1;  // its verified upper bound (-1: none claimed)
};

Verdict check_certificate(FILE* f, const CheckOptions& o);

// ---- A robot model (model.cpp): an expression DAG whose children always have smaller ids
// than their parents (so increasing id order is a forward evaluation order), the variables
// in declaration order, the equations (lhs - rhs) and the user factors, and the constraint
// formulas (paper 5.4). The parser is purely syntactic: literals are kept as decimal strings
// and turned into enclosing intervals by the evaluator (MPFI's mpfi_set_str), never via strtod.
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
// The nodes `roots` depend on, themselves included, in increasing id order.
std::vector<int> closure(const Model& m, const std::vector<int>& roots);

// True when the declared domain of v is exactly one period: both bounds are a·π + b with
// exact rationals a, b (decimal literals, pi, +, -, and * or / by a rational) and
// hi − lo = 2π exactly. An interval test cannot decide this: a decimal bound close enough
// to π passes it at any fixed precision, and leaves a gap at the seam.
bool exactly_one_period(const Model& m, const Var& v);

// ---- Interval evaluation of the model's DAG (eval.cpp): natural forward
// evaluation, the three-valued truth of the constraints (FORMAT.md, "Constraints"),
// forward-mode interval AD for the Jacobians, and HC4-Revise.
enum class Mode { Proof, Refute, Truth };

// Thrown when a check needs more work than the checker allows (Evaluator::work_limit);
// the reason of the rejection, also when the batch of proofs finds its limit passed.
inline constexpr char kTooMuchWork[] =
    "the check needs more work than the checker allows for its size";
struct WorkLimit : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Evaluator {
 public:
  // The speed layer (eval_speed.cpp): incremental evaluation, and sin, cos and the branch
  // inverses of HC4 by Arb; else (--trusted-only) every node at every evaluation, by MPFI.
  // Set before an Evaluator is made.
  static bool speed;
  explicit Evaluator(const Model& m);
  ~Evaluator();
  const Model& model() const { return m_; }
  int nv() const { return int(m_.vars.size()); }

  // Values of the nodes of `prog` on `box` (one interval per variable). Proof: true iff
  // every node is defined and finite on the whole box. Refute: false only when some node
  // is defined nowhere on the box (then no point of the box is a solution). Truth: never.
  bool eval(const std::vector<int>& prog, const Ival* box, Mode mode);
  // Kleene truth of the conjunction of every constraint on box: 0 False, 1 Unknown, 2 True.
  int feasible(const Ival* box);
  // Kleene truth of formula f on the box of the last eval() of all_atoms (count_check.cpp
  // reduces the constraints on a box with it).
  int formula_truth(int f) const { return truth(f); }
  // Proof-mode values and derivatives w.r.t. the variables whose bit is set in `dirs`.
  bool eval_ad(const std::vector<int>& prog, const Ival* box, uint64_t dirs);
  const Ival& val(int id) const { return val_[id]; }
  const Ival& der(int id, int var) const { return der_[size_t(id) * nv() + var]; }
  // HC4-Revise of equation `eq` (= 0) on box; false: the box holds no solution of it.
  bool hc4(int eq, Ival* box);
  // The value of a constant node (domain bounds); false if undefined or unbounded.
  bool constant(int id, Ival& out) const;

  std::vector<int> all_eqs, all_atoms;           // program of every equation, of every atom
  std::vector<std::vector<int>> eq_prog, factor_prog;
  Ival two_pi;
  // Node evaluations (forward, derivative, backward) so far; past `work_limit` (set by
  // main.cpp from the bytes read), eval(), eval_ad() and hc4() throw WorkLimit.
  uint64_t work = 0;
  uint64_t work_limit = UINT64_MAX;

 private:
  void charge(size_t nodes) {
    work += nodes;
    if (work > work_limit)
      throw WorkLimit(kTooMuchWork);
  }
  int apply(int id, Ival& r, const Ival* a, const Ival* b);
  int truth(int formula) const;
  void trig(bool cosine, int child, const Ival& a, Ival& r);
  void power(Ival& r, const Ival& a, int k);
  bool derive(int id);
  bool backward(int id, Ival* box);
  bool monotone_projection(Op op, const Ival& r, Ival& a, const Ival& fa);
  bool project_general(Op op, const Ival& r, Ival& a);
  void branch_inverse(Op op, const Ival& r, End e, int s, double c, Ival& out);
  void arb_inverse(Op op, const Ival& r, End e, Ival& out);  // eval_speed.cpp
  bool hull_both(Ival& a, const Ival& s);  // a ∩= (s ∪ −s)
  bool meet_nonnegative(Ival& r);
  bool project_square(Ival& r, Ival& a);

  const Model& m_;
  std::vector<Ival> val_, der_, cval_;
  // Per node: 0 defined (and finite) on the whole box, 1 partial or unbounded, 2 nowhere.
  std::vector<int> cstat_, st_;  // constant nodes (once), every node (last evaluation)
  // Incremental evaluation (eval_speed.cpp): a node is recomputed only when a variable it
  // mentions changed since it was computed (the cells of a search tree and their slabs
  // differ in one or two variables). Times of a clock: of each node's computation (0: not
  // valid), of each variable's last change, and the intervals the last evaluation saw.
  uint64_t clock_ = 1;
  std::vector<uint64_t> stamp_, changed_at_;
  std::vector<Ival> seen_;
  void note_changes(const Ival* box);
  bool fresh(int id) const;
  // The last argument of each sin or cos and its sine and cosine: sin(q)/cos(q) pairs,
  // sin/cos derivatives and neighbouring slabs hit it.
  struct TrigCache {
    Ival arg, sin, cos;
    Ival end[2], end_sin[2], end_cos[2];  // eval_speed.cpp: two recent ends and their values
    int last = 0;
  };
  std::vector<TrigCache> tc_;  // one per argument of sin or cos
  std::vector<int> tc_of_;     // per node: its cache in tc_, -1 if none
  // The speed layer's trigonometry (eval_speed.cpp): Arb's balls at the ends; a contraction
  // moves one end at a time, and the last two ends keep the other one.
  void arb_sincos(TrigCache& cache, const Ival& a);
  struct Balls;
  struct FreeBalls {  // defined where Balls is
    void operator()(Balls* b) const;
  };
  std::unique_ptr<Balls, FreeBalls> balls_;  // made on first use
  Balls& balls();
  struct Memo {
    double t = NAN, s[2], c[2];  // an end, its sine and cosine
  };
  std::vector<Memo> memo_ = std::vector<Memo>(1024);  // 2^10: the shift in eval_speed.cpp
  void ends_sin_cos(const Ival& a, End x, Ival& s, Ival& c);
  void extremum(Ival& v, const Ival& a, double off, double lo, double hi);
  Ival pi_;
  uint64_t dirs_ = 0;
  Ival t1_, t2_, t3_, t4_, g_;
};

// ---- Proofs on one box (proofs.cpp): the parametric Hansen–Sengupta test of P1/P3 with a
// recorded preconditioner and inflated box, strong regularity of C·Fx and C·Fq (P2),
// enclosures of the sign factors, and the refutation procedure for contraction slabs and
// discarded cells (HC4 fixpoint, false constraints, Hansen–Sengupta contraction with the
// checker's own preconditioner, bisection). Boxes arrive as doubles, lo/hi pairs.
struct Factor {
  enum Kind { DetFx, DetFq, DiagFx, DiagFq, User } kind;
  int arg = 0;  // 0-based entry or user factor
};

class Prover {
 public:
  explicit Prover(Evaluator& ev);
  Evaluator& evaluator() { return ev_; }
  void load(const double* lohi);  // box := the double box
  std::vector<Ival> box;          // nv intervals: the box the next call works on

  // P1/P3: y = q̌ − GS(C·Fq(x, Q), C·f(x, q̌)), x the pose part of `box`, Q the inflated box
  // (n lo/hi pairs), C row major (nullptr: the checker's own, the inverse of mid Fq).
  // Returns nullptr on success, else why it failed. With `pose` the roles swap (V
  // records): x unknown in Q, Fx for Fq, the commands of `box` fixed.
  const char* newton(const double* Q, const double* C, bool pose = false);
  std::vector<Ival> y;
  // P2 on `box`: C_X·Fx·diag(D_X) and C_Q·Fq·diag(D_Q) strictly diagonally dominant
  // (D positive; a null C: the checker's own). Keeps the Jacobians.
  const char* regular(const double* CX, const double* CQ, const double* DX, const double* DQ);
  // Enclosure of a factor on `box`; false if not defined there. `jac` says whether the
  // Jacobians of `box` are already computed (by regular()).
  bool factor(const Factor& f, bool jac, Ival& out);
  // True when `box` provably holds no feasible solution of f = 0.
  bool refute();
  // Narrows b around its feasible solutions (HC4, Hansen–Sengupta in the commands); false:
  // b holds none.
  bool contract(std::vector<Ival>& b);
  long refutations = 0, refute_boxes = 0;

 private:
  bool jacobians();
  const double* own_preconditioner(const std::vector<Ival>& J);
  bool dominant(const std::vector<Ival>& J, const double* C, const double* D);
  int hs_contract(std::vector<Ival>& b);
  bool refute_rec(std::vector<Ival>& b, int depth, int& budget);
  void product(const std::vector<Ival>& J, const double* C, std::vector<Ival>& out);
  void rhs(const double* C);
  void gs_row(int i, const std::vector<Ival>& X, const std::vector<Ival>& c);
  void read_jacobian(const std::vector<int>& cols, std::vector<Ival>& J);
  void dot(Ival& out, const double* C, const Ival* const* x);

  Evaluator& ev_;
  const Model& m_;
  int n_, nv_;
  uint64_t cmd_mask_ = 0, pose_mask_ = 0, all_mask_ = 0;
  std::vector<Ival> w_, Jx_, Jq_, A_, b_;
  // Scratch of one call at a time, kept to spare the allocations of millions of calls.
  std::vector<Ival> X_, c_, rb_;  // newton() and hs_contract(); refute()
  std::vector<double> M_, own_, w1_, w2_;  // own_preconditioner(); contract()
  Ival t1_, t2_;
};

// An approximate inverse of the n×n matrix M (row major; M is spoilt) by Gauss–Jordan in
// binary64 (proofs.cpp): a choice of preconditioner, never trusted. False when singular.
bool invert(std::vector<double>& M, int n, std::vector<double>& inv);
// The determinant of the n×n interval matrix M (row major) by cofactor expansion along the
// first row (proofs.cpp); the entire line for n > 6.
void det(const std::vector<Ival>& M, int n, Ival& out);
// Appends to m the nodes of the Jacobian of its equations, ∂f_r/∂x_v as out[r][v] (−1 where
// min, max or abs leave it without a rule): derivative.cpp.
std::vector<std::vector<int>> jacobian_nodes(Model& m);

// ---- The combinatorial half of the check (bound.cpp; fast_sweep.cpp): a union-find, the
// neighbourhood graph M of FORMAT.md ("claim lower-bound") by sort-and-sweep over the output
// boxes and their 2π-shifted copies, the separated lower bound (11), and the filtering rule.
struct UnionFind {
  std::vector<int> parent;
  void reset(size_t n);
  int find(int x);
  void unite(int a, int b);
};

// Output boxes kept compactly as doubles, with their verified factor signs.
// The ends are kept in chunks of 2^16 boxes, not one vector: a vector grown box by box holds
// up to twice its size, and three times while it moves (3-RPR at eps 0.1: 9.7 GB of ends).
struct OutBoxes {
  static constexpr int kChunkBits = 16;
  int nv = 0;
  std::vector<uint32_t> pos, neg;  // bit i: factor i verified > 0 (resp. < 0)
  std::vector<uint8_t> solution;
  size_t size() const { return solution.size(); }
  // Appends the ends of a box (2·nv: lo, hi per variable); pos, neg, solution are pushed
  // by the caller.
  void add_box(const double* lohi) {
    const size_t i = boxes_++, per = size_t(2 * nv);
    if ((i >> kChunkBits) == chunks_.size())
      chunks_.emplace_back(new double[per << kChunkBits]);
    std::copy(lohi, lohi + per, box(i));
  }
  const double* box(size_t i) const {
    return chunks_[i >> kChunkBits].get() + (i & ((size_t(1) << kChunkBits) - 1)) * 2 * nv;
  }
  double* box(size_t i) {
    return chunks_[i >> kChunkBits].get() + (i & ((size_t(1) << kChunkBits) - 1)) * 2 * nv;
  }

 private:
  size_t boxes_ = 0;
  std::vector<std::unique_ptr<double[]>> chunks_;
};

// t := x + 2πk in intervals: the bound x of a box shifted by k periods. Its ends rounded outward
// (graph M) or inward (links) to doubles give the shifted bound each check needs.
void shift_by_periods(Ival& t, const Ival& two_pi, int k, double x);

// The neighbourhood graph M, never held: a sweep hands each pair (a, b), a < b, such that
// for some shift k (k_v ∈ {−1, 0, 1} on periodic variables) a meets b + 2πk with the
// shifted bounds rounded outward, to a visitor: a superset of the pairs that share a point
// modulo 2π (a pair met through two shifts may come twice). A missing pair could raise
// the bound, so every sweep must find them all.
class PairSweep {
 public:
  virtual ~PairSweep() = default;
  // Visits every pair of M and returns how many it visited. Throws std::length_error beyond
  // `max_pairs` pairs: boxes that all overlap (one IMAGE for many cells) make M quadratic.
  // With threads > 1 `visit` is called under a lock, in an order that depends on the
  // threads; the pairs and their count do not.
  virtual size_t run(const std::function<void(int, int)>& visit, size_t max_pairs = SIZE_MAX,
                     int threads = 1) const = 0;
};

// The trusted sweep (bound.cpp): the boxes, and their copies shifted by ±2π if the sweep
// variable is periodic, sorted by lower end on it; each overlapping pair is tested by the
// rule itself, every shifted end computed in intervals. Slower, and simple.
class PlainSweep : public PairSweep {
 public:
  PlainSweep(const OutBoxes& R, const std::vector<bool>& periodic, const Ival& two_pi);
  size_t run(const std::function<void(int, int)>& visit, size_t max_pairs = SIZE_MAX,
             int threads = 1) const override;

 private:
  struct Item {
    double lo, hi;
    int id, k;
  };
  const OutBoxes& R_;
  const std::vector<bool>& periodic_;
  const Ival& two_pi_;
  std::vector<Item> items_;  // by lo
};

// Bound (11): Σ over sign vectors s of the number of components (of the boxes compatible
// with s, joined by M) holding a solution box whose signs are all verified and equal s.
// Only the factors whose bit is set in `use` separate (the others are ignored). Sweeps M
// once per group of classes, a union-find per class of a group (at most 2^28 entries).
// Throws std::length_error beyond `max_pairs` pairs, and when classes × (pairs + boxes)
// exceeds 2^32 + 2^10 per box. `pairs`, if given, receives the number of pairs of M.
long lower_bound(const OutBoxes& R, const PairSweep& M, uint32_t use, size_t max_pairs,
                 size_t* pairs = nullptr, int threads = 1);
// Filtering: cut at the largest ratio of consecutive sizes; keep all if it is < 2.
long filtered_count(const std::vector<int64_t>& sizes);

}  // namespace cc
