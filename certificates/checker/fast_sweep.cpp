// fast_sweep.cpp — speed layer: the neighbourhood graph M by a sort-and-sweep whose items
// are floats rounded outward (a superset of the overlaps), in strips of a second variable
// swept on T threads, a third variable's ends (periodic or not) tested in the items; not
// O(N²), and not 3^(periodic variables) copies: only the sweep dimension is shifted, the
// other variables are tested shift by shift. Its pairs go straight to the visitor; M is
// never held. PlainSweep (bound.cpp) finds the same pairs.
#include "speed.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>

namespace cc {

// The largest float <= x (a double beyond the floats' range has no float conversion).
static float float_down(double x) {
  if (x < -double(FLT_MAX)) return -HUGE_VALF;
  if (x > double(FLT_MAX)) return FLT_MAX;
  float f = float(x);
  return double(f) > x ? std::nextafter(f, -HUGE_VALF) : f;
}

NeighbourSweep::NeighbourSweep(const OutBoxes& R, const std::vector<bool>& periodic,
                               const Ival& two_pi)
    : R_(R), slot_(size_t(R.nv), -1) {
  const int nv = R.nv;
  const size_t N = R.size();
  for (int v = 0; v < nv; ++v)
    if (periodic[v]) slot_[v] = int(P_++);
  // The hull and mean width of the boxes per variable choose the sweep variables.
  std::vector<double> hlo(nv, 1e308), hhi(nv, -1e308), mean(nv, 0);
  for (size_t b = 0; b < N; ++b)
    for (int v = 0; v < nv; ++v) {
      const double lo = R.box(b)[2 * v], hi = R.box(b)[2 * v + 1];
      hlo[v] = std::min(hlo[v], lo);
      hhi[v] = std::max(hhi[v], hi);
      mean[v] += (hi - lo) / double(N);
    }
  // The shifted ends of the boxes on a seam (3-RPR at eps 1: 2 % of them): 4 bytes a box
  // instead of 32 per periodic variable.
  row_.assign(P_ ? N : 0, -1);
  Ival t;
  std::vector<std::array<double, 2>> row(P_ * 2);
  for (size_t b = 0; b < N && P_; ++b) {
    bool meets = false;
    for (int v = 0; v < nv; ++v) {
      if (slot_[v] < 0) continue;
      for (int k = -1; k <= 1; k += 2) {
        std::array<double, 2>& s = row[size_t(slot_[v]) * 2 + (k > 0)];
        shift_by_periods(t, two_pi, k, R.box(b)[2 * v]);
        s[0] = t.lo();
        shift_by_periods(t, two_pi, k, R.box(b)[2 * v + 1]);
        s[1] = t.hi();
        meets = meets || (s[0] <= hhi[v] && hlo[v] <= s[1]);
      }
    }
    if (!meets) continue;
    if (shifted_.size() / (2 * P_) >= size_t(INT32_MAX)) throw std::length_error("seam boxes");
    row_[b] = int32_t(shifted_.size() / (2 * P_));
    shifted_.insert(shifted_.end(), row.begin(), row.end());
  }
  // The variable v with `take(v)` where boxes are thinnest relative to their spread; -1: none.
  const auto thinnest = [&](const std::function<bool(int)>& take) {
    int best_v = -1;
    double best = -1;
    for (int v = 0; v < nv; ++v) {
      const double spread = (hhi[v] - hlo[v]) / (mean[v] + 1e-300);
      if (take(v) && spread > best) {
        best = spread;
        best_v = v;
      }
    }
    return best_v;
  };
  // Sweep on d: items are the boxes and, if d is periodic, their copies shifted in d that
  // can meet the hull.
  const int d = std::max(0, thinnest([](int) { return true; }));
  // A second, non-periodic variable e, kept in the items: pairs apart on e are dropped
  // before the test reads the boxes (3-RPR at eps 0.3: 3.8e11 candidates on d).
  const int e = thinnest([&](int v) { return v != d && !periodic[v]; });
  // A third variable g, periodic or not, whose ends the items hold too: on 3-RPR at eps 0.8
  // the pose angle separates 4.6e8 of the 5.3e8 pairs that meet on d and e (2.6e7 do).
  g_ = thinnest([&](int v) { return v != d && v != e; });
  // Strips of e, four mean widths wide: each item goes into every strip its e-interval
  // meets, and each strip is swept on its own, so that boxes far apart on e are never
  // candidates (3-RPR at eps 1: 8.0e9 candidates on d, 3.0e8 of them meet on e).
  if (e >= 0 && mean[e] > 0 && hhi[e] > hlo[e]) {
    e_lo_ = hlo[e];
    e_width_ = 4 * mean[e];
    const double wanted = std::ceil((hhi[e] - hlo[e]) / e_width_);
    strips_ = int(std::max(1.0, std::min(double(kMaxStrips), wanted)));
  }
  // The items, made twice (to count each strip's, then to place them) rather than held
  // twice: e's ends as floats rounded outward, a superset of the true overlaps on e, used
  // alike for the strips and for the test in run().
  const auto each_item = [&](const std::function<void(const Item&)>& put) {
    for (size_t b = 0; b < N; ++b)
      for (int k = periodic[d] ? -1 : 0; k <= (periodic[d] ? 1 : 0); ++k) {
        const std::array<double, 2>* c = k ? shifted(int(b), d, k) : nullptr;
        if (k && (!c || (*c)[1] < hlo[d] || (*c)[0] > hhi[d])) continue;  // meets no box
        const double* s = k ? c->data() : R.box(b) + 2 * d;
        float elo = -HUGE_VALF, ehi = HUGE_VALF, glo = -HUGE_VALF, ghi = HUGE_VALF;
        if (e >= 0) {
          elo = float_down(R.box(b)[2 * e]);
          ehi = -float_down(-R.box(b)[2 * e + 1]);
        }
        if (g_ >= 0) {
          glo = float_down(R.box(b)[2 * g_]);
          ghi = -float_down(-R.box(b)[2 * g_ + 1]);
        }
        put({float_down(s[0]), -float_down(-s[1]), elo, ehi, glo, ghi, int32_t(b), int16_t(k),
             uint16_t(strip(elo))});
      }
  };
  strip_start_.assign(size_t(strips_) + 1, 0);
  each_item([&](const Item& it) {
    for (int t = strip(it.elo); t <= strip(it.ehi); ++t) ++strip_start_[t + 1];
  });
  for (int t = 0; t < strips_; ++t) strip_start_[t + 1] += strip_start_[t];
  items_.resize(strip_start_[strips_]);
  std::vector<size_t> fill(strip_start_.begin(), strip_start_.end() - 1);
  each_item([&](const Item& it) {
    for (int t = strip(it.elo); t <= strip(it.ehi); ++t) items_[fill[t]++] = it;
  });
  for (int t = 0; t < strips_; ++t)
    std::sort(items_.begin() + long(strip_start_[t]), items_.begin() + long(strip_start_[t + 1]),
              [](const Item& x, const Item& y) { return x.lo < y.lo; });
}

// The strip of e-coordinate x: monotone in x, so a pair that meets on e meets in the strip
// of the larger of their lower ends, and in both boxes' strips.
int NeighbourSweep::strip(double x) const {
  if (strips_ == 1) return 0;
  const double t = std::floor((x - e_lo_) / e_width_);
  return t < 0 ? 0 : t >= strips_ - 1 ? strips_ - 1 : int(t);
}

// p and q are apart on g: they meet on it with no shift, nor (g periodic) with b_g shifted
// by ±2π, b the larger id (FORMAT.md), which is a_g meeting b_g + 2πk or b_g meeting
// a_g - 2πk. The shifted float ends are widened by far more than the rounding of a sum
// of doubles below 2^8 and of 2π (the test proposes a superset; the rule decides).
bool NeighbourSweep::g_apart(const Item& p, const Item& q) const {
  if (g_ < 0 || (p.glo <= q.ghi && q.glo <= p.ghi)) return false;
  if (slot_[g_] < 0) return true;
  constexpr double two_pi = 6.283185307179586, slack = 1e-9;
  for (const double k : {-two_pi, two_pi}) {  // q_g + k meets p_g
    if (double(p.glo) <= double(q.ghi) + k + slack && double(q.glo) + k - slack <= double(p.ghi))
      return false;
  }
  return true;
}

bool NeighbourSweep::sweep_strip(int t, const std::function<bool(int, int)>& put) const {
  const int nv = R_.nv;
  const size_t end = strip_start_[t + 1];
  for (size_t i = strip_start_[t]; i < end; ++i)
    for (size_t j = i + 1; j < end && items_[j].lo <= items_[i].hi; ++j) {
      const Item &p = items_[i], &q = items_[j];
      if (p.id == q.id || (p.k && q.k) || q.elo > p.ehi || p.elo > q.ehi) continue;
      if (std::max(p.strip, q.strip) != t) continue;  // met in another strip too
      if (g_apart(p, q)) continue;
      // The sweep only proposes; FORMAT.md's test decides: for every v (d too), a_v meets
      // b_v + 2πk for some k, b the larger id, its shifted ends rounded outward.
      const int a = std::min(p.id, q.id);
      const int b = std::max(p.id, q.id);
      bool meet = true;
      for (int v = 0; v < nv && meet; ++v) {
        const double* x = R_.box(a) + 2 * v;
        const double* y = R_.box(b) + 2 * v;
        meet = x[0] <= y[1] && y[0] <= x[1];
        for (int k = -1; k <= 1 && !meet && slot_[v] >= 0; k += 2) {
          const std::array<double, 2>* s = shifted(b, v, k);
          meet = s && x[0] <= (*s)[1] && (*s)[0] <= x[1];
        }
      }
      if (meet && !put(a, b)) return false;
    }
  return true;
}

// Each thread sweeps the next strip not taken and hands its pairs to `visit` in batches,
// under a lock: the scan is nearly all the time (3-RPR at eps 0.1: 97 % of the samples,
// the union-finds 3 %), and the union-finds' result does not depend on the order.
size_t NeighbourSweep::run(const std::function<void(int, int)>& visit, size_t max_pairs,
                           int threads) const {
  constexpr size_t kBatch = size_t(1) << 14;
  std::atomic<int> next{0};
  std::atomic<bool> stop{false};
  std::mutex lock;
  size_t pairs = 0;
  bool over = false;
  std::exception_ptr error;
  const auto work = [&] {
    std::vector<std::pair<int, int>> batch;
    const auto flush = [&] {
      std::lock_guard<std::mutex> hold(lock);
      try {
        over = over || pairs + batch.size() > max_pairs;
        for (size_t i = 0; i < batch.size() && !over && !error; ++i)
          visit(batch[i].first, batch[i].second);
      } catch (...) {
        if (!error) error = std::current_exception();
      }
      pairs += batch.size();
      batch.clear();
      if (over || error) stop = true;
      return !stop;
    };
    batch.reserve(kBatch);
    for (int t; !stop && (t = next++) < strips_;) {
      const bool more = sweep_strip(t, [&](int a, int b) {
        batch.emplace_back(a, b);
        return batch.size() < kBatch || flush();
      });
      if (!more) return;
    }
    flush();
  };
  std::vector<std::thread> helpers;
  for (int k = 1; k < std::min(threads, strips_); ++k) helpers.emplace_back(work);
  work();
  for (auto& h : helpers) h.join();
  if (error) std::rethrow_exception(error);
  if (over) throw std::length_error("neighbourhood graph");
  return pairs;
}

}  // namespace cc
