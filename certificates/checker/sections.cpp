// sections.cpp — trusted core: the record rules after the tree (FORMAT.md): certified
// links (P3), CSNCs connected by them, cuspidality and assembly-mode witnesses.
#include <algorithm>
#include <cmath>

#include "check.h"

namespace cc {

// SHIFT: one character of "-0+" per variable, k_v = -1, 0, +1.
std::vector<int> Checker::shifts() {
  const std::string_view s = rd.word();
  if (s.size() != size_t(nv) || s.find_first_not_of("-0+") != s.npos)
    malformed(rec(), "bad SHIFT field");
  std::vector<int> k(nv);
  for (int v = 0; v < nv; ++v) k[v] = int(s[v] == '+') - int(s[v] == '-');
  return k;
}

// Variable v of box a ∩ (box b + 2πk), the shifted ends of b rounded inward (FORMAT.md,
// "Certified links"); empty when lo > hi.
std::pair<double, double> Checker::inner(long a, long b, int v, int k) {
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
void Checker::link() {
  const size_t nn = rd.binary() ? 0 : size_t(n) * n;  // binary: the checker's own C
  rd.count(4 + 3 * size_t(n) + nn);
  const long a = index(R.size());
  const long b = index(R.size());
  if (!(a < b)) reject("link needs A < B");
  if (!R.solution[a] || !R.solution[b])
    reject("link between boxes that are not both solution boxes");
  if (std::make_pair(a, b) <= last_link) reject("links not sorted by (A, B) or repeated");
  const std::vector<int> k = shifts();
  // In a binary record the witness is coded against A's pose, Q~ against A's commands.
  const double* A = R.box(a);
  std::vector<double> w(n);
  for (int j = 0; j < n; ++j) w[j] = rd.end(A[2 * m.pose[j]], A[2 * m.pose[j] + 1], false);
  const Box Q = intervals(commands_of(A).data(), n);
  const std::vector<double> C = rd.reals(nn);
  Box X(2 * nv);  // the intersection, then the witness pose with its commands
  for (int v = 0; v < nv; ++v) {
    if (k[v] && !periodic[v]) reject("shift on a non-periodic variable");
    std::tie(X[2 * v], X[2 * v + 1]) = inner(a, b, v, k[v]);
    if (!(X[2 * v] <= X[2 * v + 1])) reject("the linked boxes do not meet");
  }
  for (int j = 0; j < n; ++j) {
    const int v = m.pose[j];
    if (!within(X[2 * v], X[2 * v + 1], w[j], w[j]))
      reject("witness outside the boxes' intersection");
    put(X, v, w[j], w[j]);
  }
  const Box commands = commands_of(X.data());
  prove([=](Prover& pr) {
    pr.load(X.data());
    return unique_zero(pr, "P3", Q, C, commands, "the command is not in both boxes");
  });
  linked.unite(int(a), int(b));  // if the proof fails, the certificate is rejected
  last_link = {a, b};
  ++out.links;
}

// csnc K SIZE IDS: component K, listed by decreasing size, is connected by verified links.
void Checker::csnc(int64_t k) {
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
std::tuple<long, long, long> Checker::pair_in_csnc(bool w, const std::tuple<long, long, long>& last,
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
void Checker::witness() {
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
void Checker::assembly() {
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
bool Checker::apart(long a, long b, int v) {
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

}  // namespace cc
