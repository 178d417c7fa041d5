#include "aspects/cuspidality.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "numerics/interval.h"
#include "aspects/neighborhood_graph.h"

namespace aspects {

const char* witness_search_name(WitnessSearch s) {
  if (s == WitnessSearch::Capped) return "capped";
  return "complete";
}

namespace {

// t := x + 2πm in MPFI at the working precision (as check_cert's shift_by_periods).
void shifted(Interval& t, const Interval& two_pi, long m, double x) {
  mpfi_mul_si(t.get(), two_pi.get(), m);
  mpfi_add_d(t.get(), t.get(), x);
}

// [al, ah] and [bl, bh] + 2πm are disjoint for every integer m: for one m, b + 2πm lies
// strictly above a and b + 2π(m − 1) strictly below it (ends rounded outward).
bool disjoint_mod_period(double al, double ah, double bl, double bh, const Interval& two_pi) {
  const double guess = std::ceil((ah - bl) / (2 * M_PI));
  if (!(std::fabs(guess) < 1048576)) return false;
  // A filter in double, with a slack far beyond the error of 2π·m in double (|m| < 2^20):
  // a pair that has no gap even then has none in MPFI, and most pairs are such.
  const double slack = 1e-9 * (1 + std::fabs(al) + std::fabs(ah) + std::fabs(bl) + std::fabs(bh));
  bool gap = false;
  for (long m = long(guess) - 1; m <= long(guess) + 1 && !gap; ++m)
    gap = ah < bl + 2 * M_PI * m + slack && bh + 2 * M_PI * (m - 1) - slack < al;
  if (!gap) return false;
  Interval t;
  for (long m = long(guess) - 1; m <= long(guess) + 1; ++m) {
    shifted(t, two_pi, m, bl);
    if (!(ah < t.lo_down())) continue;
    shifted(t, two_pi, m - 1, bh);
    if (t.hi_up() < al) return true;
  }
  return false;
}

struct Entry {
  double lo, hi;  // the sweep coordinate, shifted by 2πk and widened: a filter only
  int32_t box;
  int k;
};

}  // namespace

WitnessSpace::WitnessSpace(std::vector<int> p, std::vector<int> c, std::vector<bool> per)
    : pose(std::move(p)), command(std::move(c)), periodic(std::move(per)) {
  mpfi_const_pi(two_pi.get());
  mpfi_mul_ui(two_pi.get(), two_pi.get(), 2);
}

namespace {

// Every variable of `vars`: box b + 2πk meets box a, shifted ends of b rounded inward.
bool meet(const BoxStore& R, int a, int b, const std::vector<int>& k,
          const std::vector<int>& vars, const WitnessSpace& s) {
  Interval t;
  for (int v : vars) {
    double blo = R.lo(b, v);
    double bhi = R.hi(b, v);
    if (k[v] != 0) {
      if (!s.periodic[v]) return false;
      // A filter in double, widened far beyond rounding: most pairs fail it, without MPFI.
      const double lo = blo + 2 * M_PI * k[v], hi = bhi + 2 * M_PI * k[v];
      const double slack = 1e-9 * (1 + std::fabs(lo) + std::fabs(hi));
      if (std::max(R.lo(a, v), lo - slack) > std::min(R.hi(a, v), hi + slack)) return false;
      shifted(t, s.two_pi, k[v], blo);
      blo = t.hi_up();
      shifted(t, s.two_pi, k[v], bhi);
      bhi = t.lo_down();
    }
    if (!(std::max(R.lo(a, v), blo) <= std::min(R.hi(a, v), bhi))) return false;
  }
  return true;
}

// The non-periodic variables of `vars` (shifted by k = 0 only): [a] and [b] meet. Exact
// in double, and necessary for meet() whatever k, so it runs first: most pairs fail it.
bool meet_unshifted(const BoxStore& R, int a, int b, const std::vector<int>& vars,
                    const WitnessSpace& s) {
  for (int v : vars)
    if (!s.periodic[v] && std::max(R.lo(a, v), R.lo(b, v)) > std::min(R.hi(a, v), R.hi(b, v)))
      return false;
  return true;
}

// The periodic variables of `vars`: [a] and [b] + 2πk meet for some k in {−1, 0, 1}, in
// double with a slack far beyond rounding. Necessary for meet() with any shifts, and in
// double only: on 3-RPR at eps 1 it turns 5 M candidates of the largest CSNC into none.
bool may_meet_shifted(const BoxStore& R, int a, int b, const std::vector<int>& vars,
                      const WitnessSpace& s) {
  for (int v : vars) {
    if (!s.periodic[v]) continue;
    bool some = false;
    for (int k = -1; k <= 1 && !some; ++k) {
      const double lo = R.lo(b, v) + 2 * M_PI * k, hi = R.hi(b, v) + 2 * M_PI * k;
      const double slack = 1e-9 * (1 + std::fabs(lo) + std::fabs(hi));
      some = std::max(R.lo(a, v), lo - slack) <= std::min(R.hi(a, v), hi + slack);
    }
    if (!some) return false;
  }
  return true;
}

// Some variable of `vars` has [a] and [b] + 2πm disjoint for every integer m.
bool apart(const BoxStore& R, int a, int b, const std::vector<int>& vars, const WitnessSpace& s) {
  for (int v : vars) {
    const double al = R.lo(a, v), ah = R.hi(a, v), bl = R.lo(b, v), bh = R.hi(b, v);
    if (s.periodic[v] ? disjoint_mod_period(al, ah, bl, bh, s.two_pi) : (ah < bl || bh < al))
      return true;
  }
  return false;
}

// The non-periodic variables of `vars`, those on which the boxes overlap least (the sum of
// their widths over the span they cover) first; ties in the order of `vars`.
std::vector<int> by_overlap(const BoxStore& R, const std::vector<int32_t>& members,
                            const WitnessSpace& s, const std::vector<int>& vars) {
  std::vector<std::pair<double, int>> depth;
  for (int v : vars) {
    if (s.periodic[v]) continue;
    double widths = 0, lo = INFINITY, hi = -INFINITY;
    for (int32_t b : members) {
      widths += R.hi(b, v) - R.lo(b, v);
      lo = std::min(lo, R.lo(b, v));
      hi = std::max(hi, R.hi(b, v));
    }
    depth.push_back({widths / std::max(hi - lo, 1e-300), v});
  }
  std::stable_sort(depth.begin(), depth.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<int> order;
  for (const auto& d : depth) order.push_back(d.second);
  return order;
}

// The pairs (i, j), i < j, of sweep entries (sorted by lo on the sweep coordinate, no
// shifted copies) that meet on it and pass `candidate`, in sweep order, found strip by strip
// of a second, non-periodic coordinate v1. Two boxes that meet on v1 share the strip of the
// larger of their lower ends, where (only) the pair is tested; candidate() rejects the
// pairs that do not meet on v1, so the list is the one the plain sweep would make.
template <class Candidate>
std::vector<std::pair<int32_t, int32_t>> candidates_by_strips(const BoxStore& R, int v1,
                                                              const std::vector<Entry>& e,
                                                              Candidate candidate) {
  double lo1 = INFINITY, hi1 = -INFINITY, widths = 0;
  for (const Entry& x : e) {
    lo1 = std::min(lo1, R.lo(x.box, v1));
    hi1 = std::max(hi1, R.hi(x.box, v1));
    widths += R.hi(x.box, v1) - R.lo(x.box, v1);
  }
  std::vector<std::pair<int32_t, int32_t>> out;
  if (e.empty()) return out;
  // About 1.5 mean widths per strip: wider strips visit more pairs, narrower ones hold
  // each box in more strips (bench/RESULTS.md measures the choice). At most 65,536 strips.
  const double W = std::max(1.5 * widths / double(e.size()), (hi1 - lo1) / 65536);
  const int strips = W > 0 ? int((hi1 - lo1) / W) + 1 : 1;
  auto strip_of = [&](double x) {
    if (!(W > 0)) return 0;
    return int(std::min(double(strips - 1), std::max(0.0, std::floor((x - lo1) / W))));
  };
  std::vector<std::vector<int32_t>> in(strips);
  for (size_t i = 0; i < e.size(); ++i)
    for (int k = strip_of(R.lo(e[i].box, v1)); k <= strip_of(R.hi(e[i].box, v1)); ++k)
      in[k].push_back(int32_t(i));
  for (int k = 0; k < strips; ++k) {
    const std::vector<int32_t>& L = in[k];  // increasing entries, so increasing lo on v0
    for (size_t x = 0; x < L.size(); ++x) {
      const Entry& a = e[L[x]];
      for (size_t y = x + 1; y < L.size() && e[L[y]].lo <= a.hi; ++y) {
        const Entry& b = e[L[y]];
        if (strip_of(std::max(R.lo(a.box, v1), R.lo(b.box, v1))) != k) continue;
        if (candidate(size_t(L[x]), size_t(L[y]))) out.push_back({L[x], L[y]});
      }
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The candidate pairs A < B of one CSNC (its boxes in `members`): B + 2πk meets A on every
// variable of `meet_vars` (k on periodic ones only), A and B are apart on one variable of
// `apart_vars`. Each pair is offered to `accept` (with its first fitting k) until it takes
// it; stops when `accept` has taken `cap` pairs or been offered `offers` (then Capped).
template <class Accept>
WitnessSearch sweep(const BoxStore& R, const std::vector<int32_t>& members,
                    const WitnessSpace& s, const std::vector<int>& meet_vars,
                    const std::vector<int>& apart_vars, int64_t cap, int64_t offers,
                    Accept accept) {
  // The sweep coordinate: a non-periodic one when there is one, the one where the boxes
  // overlap least: the pairs the sweep visits are those that meet on it.
  const std::vector<int> order = by_overlap(R, members, s, meet_vars);
  const int v0 = order.empty() ? meet_vars[0] : order[0];
  std::vector<Entry> e;
  const int copies = s.periodic[v0] ? 1 : 0;
  for (int32_t b : members)
    for (int k = -copies; k <= copies; ++k) {
      const double lo = R.lo(b, v0) + 2 * M_PI * k, hi = R.hi(b, v0) + 2 * M_PI * k;
      e.push_back({lo - 1e-9 * (1 + std::fabs(lo)), hi + 1e-9 * (1 + std::fabs(hi)), b, k});
    }
  std::sort(e.begin(), e.end(), [](const Entry& x, const Entry& y) { return x.lo < y.lo; });
  // The other periodic variables: their shifts are enumerated (3^m combinations).
  std::vector<int> others;
  for (int v : meet_vars)
    if (v != v0 && s.periodic[v]) others.push_back(v);
  int combos = 1;
  for (size_t i = 0; i < others.size(); ++i) combos *= 3;
  std::vector<int> k(R.nv(), 0);
  int64_t taken = 0, offered = 0;
  // Entries i < j meet on v0. The order-free tests: a pair of distinct boxes A < B, B not
  // shifted on v0, meeting on the non-periodic variables and possibly (in double) on the
  // periodic ones, apart on one of apart_vars.
  auto candidate = [&](size_t i, size_t j) {
    if (e[i].box == e[j].box) return false;
    const bool i_first = e[i].box < e[j].box;
    const Entry& A = i_first ? e[i] : e[j];
    const Entry& B = i_first ? e[j] : e[i];
    return A.k == 0 && meet_unshifted(R, A.box, B.box, meet_vars, s) &&
           may_meet_shifted(R, A.box, B.box, meet_vars, s) &&
           apart(R, A.box, B.box, apart_vars, s);
  };
  // A candidate offered to `accept`, in sweep order; true when the search must stop.
  auto offer = [&](size_t i, size_t j) {
    const bool i_first = e[i].box < e[j].box;
    const Entry& A = i_first ? e[i] : e[j];
    const Entry& B = i_first ? e[j] : e[i];
    for (int combo = 0; combo < combos; ++combo) {
      std::fill(k.begin(), k.end(), 0);
      k[v0] = B.k;
      int code = combo;
      for (int v : others) {
        k[v] = code % 3 - 1;
        code /= 3;
      }
      if (!meet(R, A.box, B.box, k, meet_vars, s)) continue;
      ++offered;
      if (accept(A.box, B.box, k)) {
        ++taken;
        break;
      }
    }
    return taken >= cap || offered >= offers;
  };
  // With a second non-periodic coordinate, the candidates come from strips of it (the same
  // list, far fewer pairs visited than by one coordinate), and are
  // offered in sweep order. Not under a budget of offers, which a full listing would exceed.
  const int v1 = offers == INT64_MAX && copies == 0 && order.size() > 1 ? order[1] : -1;
  if (v1 >= 0) {
    for (const auto& [i, j] : candidates_by_strips(R, v1, e, candidate))
      if (offer(size_t(i), size_t(j))) return WitnessSearch::Capped;
    return WitnessSearch::Complete;
  }
  for (size_t i = 0; i < e.size(); ++i) {
    for (size_t j = i + 1; j < e.size() && e[j].lo <= e[i].hi; ++j) {
      if (!candidate(i, j)) continue;
      if (offer(i, j)) return WitnessSearch::Capped;
    }
  }
  return WitnessSearch::Complete;
}

std::vector<std::vector<int32_t>> members_of(const std::vector<int32_t>& csnc, int csncs) {
  std::vector<std::vector<int32_t>> members(csncs);
  for (size_t b = 0; b < csnc.size(); ++b)
    if (csnc[b] >= 0) members[csnc[b]].push_back(int32_t(b));
  return members;
}

// A pair met through two shifts (boxes spanning a period) is kept once.
template <class W>
void unique_pairs(std::vector<W>& w, size_t first) {
  auto lt = [](const W& x, const W& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; };
  auto eq = [](const W& x, const W& y) { return x.a == y.a && x.b == y.b; };
  std::stable_sort(w.begin() + first, w.end(), lt);
  w.erase(std::unique(w.begin() + first, w.end(), eq), w.end());
}

}  // namespace

bool poses_overlap(const BoxStore& R, int a, int b, const std::vector<int>& k,
                   const WitnessSpace& s) {
  return meet(R, a, b, k, s.pose, s);
}

bool commands_disjoint(const BoxStore& R, int a, int b, const WitnessSpace& s) {
  return apart(R, a, b, s.command, s);
}

CuspidalWitnesses find_pose_witnesses(const BoxStore& R, const std::vector<int32_t>& csnc,
                                      int csncs, const WitnessSpace& s, int64_t cap,
                                      const ForEachIndex& for_each) {
  CuspidalWitnesses w;
  w.count.assign(csncs, 0);
  w.search.assign(csncs, WitnessSearch::Complete);
  if (s.pose.empty() || s.command.empty()) return w;
  const std::vector<std::vector<int32_t>> members = members_of(csnc, csncs);
  std::vector<std::vector<PoseWitness>> found(csncs);
  for_each(csncs, [&](int32_t c) {
    auto take = [&](int32_t a, int32_t b, const std::vector<int>& k) {
      found[c].push_back({c, a, b, pack_shift(k)});
      return true;
    };
    w.search[c] = sweep(R, members[c], s, s.pose, s.command, cap, INT64_MAX, take);
    unique_pairs(found[c], 0);
    w.count[c] = int64_t(found[c].size());
  });
  for (auto& f : found) w.pose.insert(w.pose.end(), f.begin(), f.end());
  return w;
}

void find_command_witnesses(const BoxStore& R, const std::vector<int32_t>& csnc, int csncs,
                            const WitnessSpace& s, const ProveCommandWitness& prove,
                            CuspidalWitnesses& w, int64_t cap, int64_t attempts,
                            int64_t attempts_per_box, const ForEachIndex& for_each) {
  w.command.clear();
  w.command_count.assign(csncs, 0);
  w.command_search.assign(csncs, WitnessSearch::Complete);
  if (s.pose.empty() || s.command.empty()) return;
  const std::vector<std::vector<int32_t>> members = members_of(csnc, csncs);
  std::vector<std::vector<CommandWitness>> found(csncs);
  for_each(csncs, [&](int32_t c) {
    // The sweep lists the candidates (cheap), the proofs (costly) run at once, and the
    // proved ones are taken in sweep order: the same witnesses for any thread count.
    std::vector<CommandWitness> candidates;
    auto list = [&](int32_t a, int32_t b, const std::vector<int>& k) {
      CommandWitness cw;
      cw.csnc = c;
      cw.a = a;
      cw.b = b;
      cw.shift_code = pack_shift(k);
      candidates.push_back(std::move(cw));
      return false;
    };
    const int64_t per_size = attempts_per_box * int64_t(members[c].size());
    const int64_t budget = std::min(attempts, std::max(attempts / 10, per_size));
    w.command_search[c] = sweep(R, members[c], s, s.command, s.pose, INT64_MAX, budget, list);
    std::vector<uint8_t> proved(candidates.size(), 0);
    for_each(int(candidates.size()), [&](int32_t i) { proved[i] = prove(candidates[i]); });
    for (size_t i = 0; i < candidates.size(); ++i) {
      if (!proved[i]) continue;
      const CommandWitness& w_i = candidates[i];
      // Another shift of the pair just taken (the sweep offers a pair's shifts in a row).
      if (!found[c].empty() && found[c].back().a == w_i.a && found[c].back().b == w_i.b)
        continue;
      if (int64_t(found[c].size()) >= cap) {
        w.command_search[c] = WitnessSearch::Capped;
        break;
      }
      found[c].push_back(std::move(candidates[i]));
    }
    unique_pairs(found[c], 0);
    w.command_count[c] = int64_t(found[c].size());
  });
  for (auto& f : found)
    for (auto& cw : f) w.command.push_back(std::move(cw));
}

}  // namespace aspects
