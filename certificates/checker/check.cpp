// check.cpp — trusted core: the record rules of the header (model, precision, declared
// domain, factors) and of the claims, and the whole run. Reads a certificate of `aspects
// solve` record by record and re-verifies every claim with the checker's own parser,
// evaluator and proofs (FORMAT.md is the specification). Each record's structure is
// checked in order; its interval proofs run in line, or are queued (proof_batch.cpp) and
// judged in record order.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <new>
#include <thread>

#include "check.h"

namespace cc {

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}
}  // namespace

void Checker::header() {
  rd.next();
  count = rd.size() == 2 && rd.kind() == "aspects-count-certificate";
  if (rd.size() != 2 || (rd.kind() != "aspects-certificate" && !count))
    malformed(rec(), "not an aspects certificate");
  const std::string_view v = rd.word();
  if (count ? v != "1" : v != "1" && v != "2" && v != "3")
    malformed(rec(), "unknown certificate version '" + std::string(v) + "'");
  version = count ? 2 : v[0] - '0';  // a count certificate's tree is version 2's
  rd.expect({"tool", "aspects"}, 1);  // the writer's version: free text (FORMAT.md)
  read_model();
  read_domain();
  const int64_t count = rd.expect({"factors"}, 1).integer();
  if (count < 0 || count > 20) reject("number of factors out of range 0..20");
  p = int(count);
  for (int i = 0; i < p; ++i) factors.push_back(read_factor());
  if (version == 3) rd.allow_binary(n, nv, p);
  rd.expect({"tree"}, 0);
  R.nv = nv;
}

// The model record, its text, the precision and the declared bounds.
void Checker::read_model() {
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
  set_interval_precision(mpfr_prec_t(prec), speed);  // doubles at 53 bits
  Evaluator::speed = speed;
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
void Checker::read_bounds(long model_rec) {
  dlo.resize(nv);
  dhi.resize(nv);
  for (int v = 0; v < nv; ++v) {
    const Var& x = m.vars[v];
    const std::string what = "embedded model: ";
    if (!ev->constant(x.lo, dlo[v]) || !ev->constant(x.hi, dhi[v]))
      malformed(model_rec, what + "domain bound of '" + x.name + "' is not a finite number");
    const bool reversed = less(dhi[v], Hi, dlo[v], Lo);
    if (reversed || less(dhi[v], Lo, dlo[v], Hi))
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
void Checker::read_domain() {
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
Factor Checker::read_factor() {
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
void Checker::require_triangular(Factor::Kind kind, std::string_view name) {
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

// claim filtered, claim lower-bound and end; the bound is recomputed from the verified
// boxes. Returns the number of pairs of the neighbourhood graph M.
size_t Checker::claims(const CheckOptions& o) {
  if (rd.require({"claim", "filtered"}, 1).integer() != filtered_count(sizes))
    reject("claim filtered does not match the filtering rule");
  const int64_t claim = rd.expect({"claim", "lower-bound"}, 1).integer();
  const long claim_rec = rec();
  if (claim < 0) malformed(rec(), "negative lower bound");
  const int64_t records = rd.expect({"end"}, 1).integer();
  if (records != rec() - 1) malformed(rec(), "end: wrong record count");
  rd.expect_eof();
  flush();  // every proof judged before the bound
  // The links and CSNCs are judged: their 8 bytes a box make room for M (3-RPR at eps 0.1:
  // 0.8 GB, which put the check's peak above the solver's).
  std::vector<int>().swap(linked.parent);
  std::vector<int32_t>().swap(csnc_of);
  // A real subdivision has a few neighbours per box, while S records that share one IMAGE
  // over many cells make M quadratic (10^5 boxes: 5·10^9 pairs): rejected instead.
  const size_t max_pairs = (size_t(1) << 22) + 64 * R.size();
  const auto t0 = Clock::now();
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
  graph_seconds_ = seconds_since(t0);
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

void Checker::run(const CheckOptions& o) {
  const auto t0 = Clock::now();
  if (const char* e = std::getenv("CHECK_CERT_WORK_BASE"))
    work_base = std::max(10, std::min(40, std::atoi(e)));
  speed = !o.trusted_only;
  rd.print(o.print);
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
  // Every rank ran its share of the proofs (ranks.cpp): the statistics are the sums.
  uint64_t done[2] = {uint64_t(batch ? batch->refutations() : prover->refutations),
                      uint64_t(batch ? batch->refute_boxes() : prover->refute_boxes)};
  ranks::sum(done, 2);
  if (o.quiet) return;
  std::fprintf(stderr,
               "check_cert: %ld refutations (%ld boxes), %llu node evaluations, tree %.2f s, %zu "
               "pairs in M (%.2f s), recomputed lower bound %ld, %d thread%s%s, %.2f s\n",
               long(done[0]), long(done[1]), (unsigned long long)(batch ? batch->work : ev->work),
               tree_seconds_, pairs_, graph_seconds_, out.recomputed, threads,
               threads > 1 ? "s" : "",
               ranks::size() > 1 ? (" x " + std::to_string(ranks::size()) + " ranks").c_str()
                                 : "",
               seconds_since(t0));
}

// Every section after the header; the proofs are queued and judged in record order.
void Checker::body(const CheckOptions& o) {
  const auto t0 = Clock::now();
  tree();
  flush();  // the tree's last proofs, so that its time is theirs
  tree_seconds_ = seconds_since(t0);
  if (count) {
    count_body();
    return;
  }
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

}  // namespace cc

const char* cc::outcome_name(Outcome o) {
  static const char* const names[] = {"VERIFIED", "REJECTED", "MALFORMED", "UNCHECKED"};
  return names[int(o)];
}

cc::Verdict cc::check_certificate(FILE* f, const CheckOptions& o) {
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
    // On one rank alone, maybe, while the others wait for it: the job ends.
    if (ranks::size() > 1) ranks::abort_all("out of memory");
    out.outcome = Outcome::Rejected;
    out.reason = "out of memory";
  } catch (const std::exception& e) {
    if (ranks::size() > 1) ranks::abort_all(std::string("internal error: ") + e.what());
    out.outcome = Outcome::Rejected;
    out.reason = std::string("internal error: ") + e.what();
  }
  if (c) c->rd.finish_print();  // the record the check stopped at
  return out;
}
