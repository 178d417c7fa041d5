#include "cuspidality.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "interval.h"
#include "neighborhood_graph.h"

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

bool poses_overlap(const BoxStore& R, int a, int b, const std::vector<int>& k,
                   const WitnessSpace& s) {
  Interval t;
  for (int v : s.pose) {
    double blo = R.lo(b, v);
    double bhi = R.hi(b, v);
    if (k[v] != 0) {
      if (!s.periodic[v]) return false;
      shifted(t, s.two_pi, k[v], blo);
      blo = t.hi_up();
      shifted(t, s.two_pi, k[v], bhi);
      bhi = t.lo_down();
    }
    if (!(std::max(R.lo(a, v), blo) <= std::min(R.hi(a, v), bhi))) return false;
  }
  return true;
}

bool commands_disjoint(const BoxStore& R, int a, int b, const WitnessSpace& s) {
  for (int v : s.command) {
    const double al = R.lo(a, v), ah = R.hi(a, v), bl = R.lo(b, v), bh = R.hi(b, v);
    if (s.periodic[v] ? disjoint_mod_period(al, ah, bl, bh, s.two_pi) : (ah < bl || bh < al))
      return true;
  }
  return false;
}

namespace {

// The witnesses of one CSNC (its boxes in `members`), appended to `out`; returns the
// outcome of the search.
WitnessSearch sweep(const BoxStore& R, const std::vector<int32_t>& members, int32_t c,
                    const WitnessSpace& s, int v0, int64_t cap, std::vector<PoseWitness>& out) {
  std::vector<Entry> e;
  const int copies = s.periodic[v0] ? 1 : 0;
  for (int32_t b : members)
    for (int k = -copies; k <= copies; ++k) {
      const double lo = R.lo(b, v0) + 2 * M_PI * k, hi = R.hi(b, v0) + 2 * M_PI * k;
      e.push_back({lo - 1e-9 * (1 + std::fabs(lo)), hi + 1e-9 * (1 + std::fabs(hi)), b, k});
    }
  std::sort(e.begin(), e.end(), [](const Entry& x, const Entry& y) { return x.lo < y.lo; });
  // The other periodic pose variables: their shifts are enumerated (3^m combinations).
  std::vector<int> others;
  for (int v : s.pose)
    if (v != v0 && s.periodic[v]) others.push_back(v);
  int combos = 1;
  for (size_t i = 0; i < others.size(); ++i) combos *= 3;
  std::vector<int> k(R.nv(), 0);
  const size_t first = out.size();
  for (size_t i = 0; i < e.size(); ++i) {
    for (size_t j = i + 1; j < e.size() && e[j].lo <= e[i].hi; ++j) {
      if (e[i].box == e[j].box) continue;
      const bool i_first = e[i].box < e[j].box;
      const Entry& A = i_first ? e[i] : e[j];
      const Entry& B = i_first ? e[j] : e[i];
      if (A.k != 0 || !commands_disjoint(R, A.box, B.box, s)) continue;
      for (int combo = 0; combo < combos; ++combo) {
        std::fill(k.begin(), k.end(), 0);
        k[v0] = B.k;
        int code = combo;
        for (int v : others) {
          k[v] = code % 3 - 1;
          code /= 3;
        }
        if (!poses_overlap(R, A.box, B.box, k, s)) continue;
        out.push_back({c, A.box, B.box, pack_shift(k)});
        break;
      }
      if (int64_t(out.size() - first) >= cap) return WitnessSearch::Capped;
    }
  }
  return WitnessSearch::Complete;
}

}  // namespace

CuspidalWitnesses find_pose_witnesses(const BoxStore& R, const std::vector<int32_t>& csnc,
                                      int csncs, const WitnessSpace& s, int64_t cap) {
  CuspidalWitnesses w;
  w.count.assign(csncs, 0);
  w.search.assign(csncs, WitnessSearch::Complete);
  if (s.pose.empty() || s.command.empty()) return w;
  int v0 = s.pose[0];  // the sweep coordinate: a non-periodic one when there is one
  for (int v : s.pose)
    if (!s.periodic[v]) {
      v0 = v;
      break;
    }
  std::vector<std::vector<int32_t>> members(csncs);
  for (int b = 0; b < R.size(); ++b)
    if (csnc[b] >= 0) members[csnc[b]].push_back(b);
  for (int32_t c = 0; c < csncs; ++c) {
    const size_t first = w.pose.size();
    w.search[c] = sweep(R, members[c], c, s, v0, cap, w.pose);
    // A pair met through two shifts (boxes spanning a period) is kept once.
    auto lt = [](const PoseWitness& x, const PoseWitness& y) {
      return x.a != y.a ? x.a < y.a : x.b < y.b;
    };
    auto eq = [](const PoseWitness& x, const PoseWitness& y) { return x.a == y.a && x.b == y.b; };
    std::stable_sort(w.pose.begin() + first, w.pose.end(), lt);
    w.pose.erase(std::unique(w.pose.begin() + first, w.pose.end(), eq), w.pose.end());
    w.count[c] = int64_t(w.pose.size() - first);
  }
  return w;
}

}  // namespace aspects
