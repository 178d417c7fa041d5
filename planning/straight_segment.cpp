#include "straight_segment.h"

#include <mpfi.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "results/pose.h"

namespace aspects {

const char* segment_check_name(SegmentCheck c) {
  switch (c) {
    case SegmentCheck::Certified: return "certified";
    case SegmentCheck::NotInCsnc: return "box_of_another_csnc";
    case SegmentCheck::EndOutside: return "end_outside_its_box";
    case SegmentCheck::CrossingOutside: return "crossing_outside_its_boxes";
    case SegmentCheck::CrossingsUnordered: return "crossings_unordered";
    case SegmentCheck::NotLinked: return "boxes_not_linked";
    case SegmentCheck::Malformed: return "malformed";
  }
  return "?";
}

namespace {

// Enclosures at a fixed precision, whatever the working precision of the result: the
// crossings are checked once, and a wider enclosure would only refuse more of them.
constexpr mpfr_prec_t kPrec = 192;

struct Iv {
  mpfi_t v;
  Iv() { mpfi_init2(v, kPrec); }
  ~Iv() { mpfi_clear(v); }
  Iv(const Iv&) = delete;
  Iv& operator=(const Iv&) = delete;
};

// out = x + 2π·k
void shifted(mpfi_t out, double x, long k) {
  mpfi_const_pi(out);
  mpfi_mul_si(out, out, 2 * k);
  mpfi_add_d(out, out, x);
}

// p + 2πk >= b, and <= b, decided exactly (false when undecided).
bool at_least(double p, long k, double b) { return k == 0 ? p >= b : shifted_sign(p, k, b) > 0; }
bool at_most(double p, long k, double b) { return k == 0 ? p <= b : shifted_sign(p, k, b) < 0; }

bool coordinate_in(const IndexSolutionBox& s, int v, double p, long k) {
  return at_least(p, k, s.lo[v]) && at_most(p, k, s.hi[v]);
}

// The crossing's parameter t (an exact real) enclosed in `t`; its point checked in both
// placed boxes. False when not proved.
bool crossing_in(const LoadedResult& r, const UnwrappedPose& from, const UnwrappedPose& to,
                 const Crossing& c, const PlacedBox& a, const PlacedBox& b, mpfi_t t) {
  const Model& m = r.model;
  const size_t d = m.pose.size();
  if (c.coordinate < 0 || size_t(c.coordinate) >= d) return false;
  const int j = c.coordinate;
  const IndexSolutionBox& sa = r.index.solutions[a.solution];
  const IndexSolutionBox& sb = r.index.solutions[b.solution];
  // Coordinate j is exactly value + 2π·turns: decided exactly in both boxes.
  for (const auto* pb : {&a, &b}) {
    const IndexSolutionBox& s = pb == &a ? sa : sb;
    if (!m.vars[m.pose[j]].periodic && (c.turns != 0 || pb->shift[j] != 0)) return false;
    if (!coordinate_in(s, m.pose[j], c.value, c.turns - pb->shift[j])) return false;
  }
  Iv p, q, dj, target;
  shifted(p.v, from.pose[j], from.turns[j]);
  shifted(q.v, to.pose[j], to.turns[j]);
  mpfi_sub(dj.v, q.v, p.v);
  if (mpfi_has_zero(dj.v)) return false;
  shifted(target.v, c.value, c.turns);
  mpfi_sub(t, target.v, p.v);
  mpfi_div(t, t, dj.v);
  for (size_t i = 0; i < d; ++i) {
    if (int(i) == j) continue;
    Iv pi, qi, x, lo, hi;
    shifted(pi.v, from.pose[i], from.turns[i]);
    shifted(qi.v, to.pose[i], to.turns[i]);
    mpfi_sub(x.v, qi.v, pi.v);
    mpfi_mul(x.v, x.v, t);
    mpfi_add(x.v, x.v, pi.v);
    for (const auto* pb : {&a, &b}) {
      const IndexSolutionBox& s = pb == &a ? sa : sb;
      const int v = m.pose[i];
      shifted(lo.v, s.lo[v], pb->shift[i]);
      shifted(hi.v, s.hi[v], pb->shift[i]);
      if (mpfr_cmp(&x.v->left, &lo.v->right) < 0 || mpfr_cmp(&x.v->right, &hi.v->left) > 0)
        return false;
    }
  }
  return true;
}

}  // namespace

bool in_placed_box(const LoadedResult& r, const UnwrappedPose& x, const PlacedBox& b) {
  const Model& m = r.model;
  const IndexSolutionBox& s = r.index.solutions[b.solution];
  for (size_t j = 0; j < m.pose.size(); ++j) {
    const long k = x.turns[j] - b.shift[j];
    if (!m.vars[m.pose[j]].periodic && k != 0) return false;
    if (!coordinate_in(s, m.pose[j], x.pose[j], k)) return false;
  }
  return true;
}

SegmentCheck check_segment(const LoadedResult& r, CsncLinks& links, const UnwrappedPose& from,
                           const UnwrappedPose& to, const Segment& s) {
  const size_t d = r.model.pose.size();
  if (s.boxes.empty() || s.crossings.size() + 1 != s.boxes.size() || from.pose.size() != d ||
      to.pose.size() != d || from.turns.size() != d || to.turns.size() != d)
    return SegmentCheck::Malformed;
  // Whole turns only where the model is 2π-periodic: elsewhere a shifted box is no box.
  for (size_t j = 0; j < d; ++j)
    if (!r.model.vars[r.model.pose[j]].periodic && (from.turns[j] != 0 || to.turns[j] != 0))
      return SegmentCheck::Malformed;
  for (const PlacedBox& b : s.boxes) {
    if (b.solution >= r.index.solutions.size() || b.shift.size() != d) return SegmentCheck::Malformed;
    for (size_t j = 0; j < d; ++j)
      if (!r.model.vars[r.model.pose[j]].periodic && b.shift[j] != 0) return SegmentCheck::Malformed;
    if (r.index.solutions[b.solution].csnc != links.csnc()) return SegmentCheck::NotInCsnc;
  }
  if (!in_placed_box(r, from, s.boxes.front()) || !in_placed_box(r, to, s.boxes.back()))
    return SegmentCheck::EndOutside;
  Iv previous;  // the last crossing's t; starts at 0
  mpfi_set_si(previous.v, 0);
  for (size_t i = 0; i < s.crossings.size(); ++i) {
    Iv t;
    if (!crossing_in(r, from, to, s.crossings[i], s.boxes[i], s.boxes[i + 1], t.v))
      return SegmentCheck::CrossingOutside;
    if (mpfr_cmp(&t.v->left, &previous.v->right) < 0) return SegmentCheck::CrossingsUnordered;
    mpfi_set(previous.v, t.v);
  }
  if (mpfr_cmp_si(&previous.v->right, 1) > 0) return SegmentCheck::CrossingsUnordered;
  for (size_t i = 0; i + 1 < s.boxes.size(); ++i)
    if (!(s.boxes[i] == s.boxes[i + 1]) && !links.linked(s.boxes[i], s.boxes[i + 1]))
      return SegmentCheck::NotLinked;
  return SegmentCheck::Certified;
}

namespace {

struct Range {
  double a = 0, b = 0;  // the segment's t inside the placed box, approximately
  int exit = -1;        // the coordinate whose face ends it
  bool empty() const { return a > b; }
};

double unwrapped(const UnwrappedPose& x, size_t j) { return x.pose[j] + 2 * M_PI * double(x.turns[j]); }

Range range_in(const LoadedResult& r, const UnwrappedPose& from, const UnwrappedPose& to,
               const PlacedBox& b) {
  const Model& m = r.model;
  const IndexSolutionBox& s = r.index.solutions[b.solution];
  Range out{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), -1};
  for (size_t j = 0; j < m.pose.size(); ++j) {
    const double lo = s.lo[m.pose[j]] + 2 * M_PI * double(b.shift[j]);
    const double hi = s.hi[m.pose[j]] + 2 * M_PI * double(b.shift[j]);
    const double p = unwrapped(from, j), dp = unwrapped(to, j) - p;
    if (dp == 0) {
      if (p < lo || p > hi) return Range{1, 0, -1};
      continue;
    }
    double t1 = (lo - p) / dp, t2 = (hi - p) / dp;
    if (dp < 0) std::swap(t1, t2);
    out.a = std::max(out.a, t1);
    if (t2 < out.b) out.b = t2, out.exit = int(j);
  }
  return out;
}

}  // namespace

bool find_segment(const LoadedResult& r, CsncLinks& links, const UnwrappedPose& from,
                  const UnwrappedPose& to, const PlacedBox& start, Segment& s) {
  const Model& m = r.model;
  const size_t d = m.pose.size();
  constexpr double kSlack = 1e-12;
  s.boxes = {start};
  s.crossings.clear();
  double t = 0;
  size_t best_dim = 0;
  for (size_t j = 0; j < d; ++j)
    if (std::fabs(unwrapped(to, j) - unwrapped(from, j)) >
        std::fabs(unwrapped(to, best_dim) - unwrapped(from, best_dim)))
      best_dim = j;
  for (size_t step = 0; step <= links.boxes().size(); ++step) {
    const PlacedBox cur = s.boxes.back();
    const Range here = range_in(r, from, to, cur);
    if (here.empty() || here.b < t - kSlack || here.a > t + kSlack) return false;
    if (here.b >= 1) return true;
    // The next box: linked, met before this one ends, reaching farthest (greedy cover).
    struct Candidate {
      PlacedBox box;
      Range range;
    };
    std::vector<Candidate> next;
    for (const BoxNeighbor& nb : links.neighbors(cur.solution)) {
      PlacedBox p{nb.other, cur.shift};
      const std::vector<long> k = links.pose_shift(nb.shift_code);
      for (size_t j = 0; j < d; ++j) p.shift[j] += k[j];
      const Range there = range_in(r, from, to, p);
      if (there.empty() || there.a > here.b + kSlack || there.b <= here.b + kSlack) continue;
      if (std::any_of(next.begin(), next.end(), [&](const Candidate& c) { return c.box == p; }))
        continue;
      next.push_back({p, there});
    }
    std::sort(next.begin(), next.end(),
              [](const Candidate& x, const Candidate& y) { return x.range.b > y.range.b; });
    bool moved = false;
    for (const Candidate& c : next) {
      if (!links.linked(cur, c.box)) continue;
      const double lo_t = std::max(c.range.a, t), hi_t = here.b;
      Crossing x;
      double at = hi_t;
      if (hi_t - lo_t > 1e-9) {
        // Boxes that overlap along the segment: cross in the middle of the overlap.
        at = 0.5 * (lo_t + hi_t);
        x.coordinate = int(best_dim);
        x.turns = cur.shift[best_dim];
        const double p = unwrapped(from, best_dim);
        x.value = p + at * (unwrapped(to, best_dim) - p) - 2 * M_PI * double(x.turns);
      } else {
        // Boxes that share a face: cross on it, where the segment leaves this box.
        if (here.exit < 0) return false;
        x.coordinate = here.exit;
        x.turns = cur.shift[here.exit];
        const int v = m.pose[here.exit];
        const IndexSolutionBox& sc = r.index.solutions[cur.solution];
        x.value = unwrapped(to, here.exit) > unwrapped(from, here.exit) ? sc.hi[v] : sc.lo[v];
      }
      s.crossings.push_back(x);
      s.boxes.push_back(c.box);
      t = std::max(t, at);
      moved = true;
      break;
    }
    if (!moved) return false;
  }
  return false;
}

}  // namespace aspects
