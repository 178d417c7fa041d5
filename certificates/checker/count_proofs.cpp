// count_proofs.cpp — trusted core: the proofs on one box that a count certificate's records
// rest on (count_check.h): Hansen–Sengupta with the unknowns a chart chooses, points of W_s,
// pavings of a chart that show a piece empty, and refutations of a class on a box.
#include "count_check.h"

namespace cc {

// ---------------------------------------------------------------- proofs

// Hansen–Sengupta with the variables w unknown: y = w̌ − GS(C·J_w(box), C·f(w̌)), C an
// approximate inverse of the midpoint of J_w (any real matrix is sound), w̌ the binary64
// middle of box's w. Every zero of f in box has its w in box_w ∩ y (each row intersected
// with box_w before the next uses it); Empty when that is empty: box holds no zero. With
// y ⊆ int box_w, each u of box's other variables has exactly one w in box_w with f = 0
// (the parametric theorem, as for P1).
Hs CountCheck::hansen_sengupta(std::vector<Ival>& box, const std::vector<int>& w,
                               std::vector<Ival>& y) {
  Evaluator& ev = *c_.ev;
  const Model& m = c_.m;
  const int n = n_;
  std::vector<int> u;  // the parameters
  for (int v = 0; v < nv_; ++v)
    if (std::find(w.begin(), w.end(), v) == w.end()) u.push_back(v);
  limit();
  if (!ev.eval_ad(ev.all_eqs, box.data(), ~uint64_t(0) >> (64 - nv_))) return Hs::Failed;
  std::vector<Ival> J(size_t(n) * n), Ju(size_t(n) * n), A(size_t(n) * n), b(n), X(n), ctr(n);
  std::vector<Ival> f(n);
  std::vector<double> M(size_t(n) * n), C;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      J[i * n + j] = ev.der(m.eqs[i], w[j]);
      Ju[i * n + j] = ev.der(m.eqs[i], u[j]);
      M[i * n + j] = 0.5 * (J[i * n + j].lo() + J[i * n + j].hi());
    }
  if (!invert(M, n, C)) return Hs::Failed;
  Ival t, s;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      set_si(A[i * n + j], 0);
      for (int k = 0; k < n; ++k) {
        mul_d(t, J[k * n + j], C[i * n + k]);
        add(A[i * n + j], A[i * n + j], t);
      }
    }
  std::vector<Ival> pt = box;
  for (int j = 0; j < n; ++j) {
    X[j] = box[w[j]];
    const double lo = X[j].lo(), hi = X[j].hi();
    const double mid = std::min(std::max(lo + 0.5 * (hi - lo), lo), hi);
    ctr[j].set(mid, mid);
    pt[w[j]] = ctr[j];
  }
  // f(U, w̌), enclosed by the natural form met with the centred one f(ǔ, w̌) + ∂_u f(box)·(U − ǔ)
  // (the mean value theorem on the segment from (ǔ, w̌) to (u, w̌), inside box): both
  // enclose it, so an empty meet cannot happen but by a bug, and fails.
  if (!ev.eval(ev.all_eqs, pt.data(), Mode::Proof)) return Hs::Failed;
  for (int i = 0; i < n; ++i) f[i] = ev.val(m.eqs[i]);
  std::vector<Ival> du(n);
  for (int k = 0; k < n; ++k) {
    const double lo = box[u[k]].lo(), hi = box[u[k]].hi();
    const double mid = std::min(std::max(lo + 0.5 * (hi - lo), lo), hi);
    pt[u[k]].set(mid, mid);
    du[k].set(mid, mid);
    sub(du[k], box[u[k]], du[k]);
  }
  if (!ev.eval(ev.all_eqs, pt.data(), Mode::Proof)) return Hs::Failed;
  for (int i = 0; i < n; ++i) {
    Ival fc = ev.val(m.eqs[i]);
    for (int k = 0; k < n; ++k) {
      mul(t, Ju[i * n + k], du[k]);
      add(fc, fc, t);
    }
    if (!f[i].meet(fc)) return Hs::Failed;
  }
  for (int i = 0; i < n; ++i) {
    set_si(b[i], 0);
    for (int k = 0; k < n; ++k) {
      mul_d(t, f[k], C[i * n + k]);
      add(b[i], b[i], t);
    }
  }
  y.resize(n);
  for (int i = 0; i < n; ++i) {
    const Ival& aii = A[i * n + i];
    if (aii.has_zero() || !aii.bounded()) return Hs::Failed;
    t = b[i];
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      sub(s, X[j], ctr[j]);
      mul(s, s, A[i * n + j]);
      add(t, t, s);
    }
    div(t, t, aii);
    sub(y[i], ctr[i], t);
    if (!y[i].bounded() || y[i].empty()) return Hs::Failed;
    if (!X[i].meet(y[i])) return Hs::Empty;
  }
  return Hs::Image;
}

bool CountCheck::refute(const Box& b) {
  limit();
  pr_.load(b.data());
  return pr_.refute();
}

// No point of class s in b: b, contracted around its solutions, holds none, or a factor's
// enclosure on what is left excludes s; else both halves of b (widest variable), to depth 10.
bool CountCheck::no_class(std::vector<Ival> b, Mask cls, int depth, long& budget) {
  limit();
  if (!pr_.contract(b)) return true;
  if ((excluded(b) >> cls) & 1) return true;
  if (depth >= 10 || --budget < 0) return false;
  int v = 0;
  double best = -1;
  for (int k = 0; k < nv_; ++k)
    if (b[k].hi() - b[k].lo() > best) best = b[k].hi() - b[k].lo(), v = k;
  if (!(best > 0)) return false;
  std::vector<Ival> c = b;
  Ival m;
  mid(m, b[v]);
  copy_end(b[v], Hi, m, Lo);
  copy_end(c[v], Lo, m, Lo);
  return no_class(std::move(b), cls, depth + 1, budget) &&
         no_class(std::move(c), cls, depth + 1, budget);
}

// The factors' enclosures on box; false when one is not defined there.
bool CountCheck::factors(const std::vector<Ival>& box, std::vector<Ival>& out) {
  limit();
  pr_.box = box;
  out.resize(c_.p);
  for (int i = 0; i < c_.p; ++i)
    if (!pr_.factor(c_.factors[i], i > 0, out[i])) return false;
  return true;
}

bool CountCheck::feasible(const std::vector<Ival>& b) {
  limit();
  return c_.ev->feasible(b.data()) == 2;
}

// Kleene's truth of each atom on the box (eval.cpp) decides the formula at every point of the
// box where it is True or False; what is left of an Unknown formula, as a disjunction of
// conjunctions of atoms: an atom's is itself, an `and`'s the products of its Unknown
// conjuncts' terms, an `or`'s the union of its Unknown disjuncts' terms. False: too many.
namespace {
std::vector<std::vector<int>> dnf_product(const std::vector<std::vector<int>>& a,
                                          const std::vector<std::vector<int>>& b) {
  std::vector<std::vector<int>> out;
  for (const auto& x : a)
    for (const auto& y : b) {
      std::vector<int> t = x;
      t.insert(t.end(), y.begin(), y.end());
      std::sort(t.begin(), t.end());
      t.erase(std::unique(t.begin(), t.end()), t.end());
      out.push_back(std::move(t));
    }
  return out;
}
}  // namespace

bool CountCheck::reduce_formula(int f, Dnf& dnf) {
  const Formula& F = c_.m.formulas[f];
  if (F.kind == Formula::Atom) {
    dnf = {{f}};
    return true;
  }
  const bool is_and = F.kind == Formula::And;
  dnf.clear();
  if (is_and) dnf = {{}};
  for (int k : F.kids) {
    if (c_.ev->formula_truth(k) != 1) continue;  // True conjunct, False disjunct: dropped
    Dnf kid;
    if (!reduce_formula(k, kid)) return false;
    if (is_and) dnf = dnf_product(dnf, kid);
    else dnf.insert(dnf.end(), kid.begin(), kid.end());
    if (dnf.size() > kMaxTerms) return false;
  }
  return true;
}

CountCheck::Reduced CountCheck::reduce(const std::vector<Ival>& b, Dnf& terms) {
  terms.clear();
  if (c_.m.constraints.empty()) return Reduced::True;
  limit();
  if (c_.ev->feasible(b.data()) == 0) return Reduced::False;  // evaluates every atom on b
  Dnf all{{}};
  bool unknown = false, fits = true;
  for (int c : c_.m.constraints) {
    if (c_.ev->formula_truth(c) != 1) continue;  // True (none is False)
    unknown = true;
    Dnf d;
    fits = fits && reduce_formula(c, d);
    if (fits) all = dnf_product(all, d);
    fits = fits && all.size() <= kMaxTerms;
  }
  if (!unknown) return Reduced::True;
  if (fits) terms = std::move(all);
  return fits && terms.size() == 1 ? Reduced::Atoms : Reduced::Disjunction;
}

// The classes no point of the box can have: some factor's enclosure on the box is ≤ 0
// where the class needs it > 0, or ≥ 0 where it needs it < 0.
Mask CountCheck::excluded(const std::vector<Ival>& b) {
  std::vector<Ival> g;
  if (!factors(b, g)) return 0;
  Mask out = 0;
  for (Mask s = 0; s < (Mask(1) << c_.p); ++s)
    for (int i = 0; i < c_.p; ++i) {
      const bool positive = (s >> i) & 1;
      if (positive ? g[i].end_sign(Hi) <= 0 : g[i].end_sign(Lo) >= 0) out |= Mask(1) << s;
    }
  return out;
}
Mask CountCheck::excluded(const Box& b) { return excluded(ivals(b)); }

// A point of W_s in the cell's box: at the u-point, Hansen–Sengupta in w (from the hint,
// ε-inflated) proves a unique zero in H, which lies in the box and in the declared domain,
// and on {u} × H every factor has the sign of class s.
bool CountCheck::point(const Box& box, const std::vector<int>& w, const std::vector<double>& u,
                       const Box& hint, Mask cls, std::vector<Ival>* at) {
  std::vector<int> uv;
  for (int v = 0; v < nv_; ++v)
    if (std::find(w.begin(), w.end(), v) == w.end()) uv.push_back(v);
  std::vector<Ival> b(nv_);
  for (int k = 0; k < n_; ++k) {
    const int v = uv[k];
    if (!within(box[2 * v], box[2 * v + 1], u[k], u[k])) return false;
    if (!c_.periodic[v] && !c_.within_domain(v, u[k], u[k])) return false;
    b[v].set(u[k], u[k]);
  }
  Box X = hint;
  auto inflate = [&](Box& x) {
    for (int j = 0; j < n_; ++j) {
      const double lo = x[2 * j], hi = x[2 * j + 1], mid = 0.5 * (lo + hi);
      const double r = 0.55 * (hi - lo) + 1e-13 * (1 + std::fabs(mid));
      x[2 * j] = std::nextafter(std::min(lo, mid - r), -INFINITY);
      x[2 * j + 1] = std::nextafter(std::max(hi, mid + r), INFINITY);
    }
  };
  inflate(X);
  std::vector<Ival> y;
  for (int it = 0; it < 12; ++it) {
    for (int j = 0; j < n_; ++j) b[w[j]].set(X[2 * j], X[2 * j + 1]);
    if (hansen_sengupta(b, w, y) != Hs::Image) return false;
    bool inside_x = true;
    for (int j = 0; j < n_; ++j) inside_x = inside_x && inside(y[j], X[2 * j], X[2 * j + 1], true);
    if (inside_x) {
      // The zero is unique in X and lies in y: further steps on y enclose it more tightly
      // (a first image from a wide hint can be too wide for the box).
      std::vector<Ival> y2;
      for (int again = 0; again < 8; ++again) {
        for (int j = 0; j < n_; ++j) b[w[j]] = y[j];
        if (hansen_sengupta(b, w, y2) != Hs::Image) break;
        for (int j = 0; j < n_; ++j)
          if (!y[j].meet(y2[j])) return false;
      }
      for (int j = 0; j < n_; ++j) {
        const int v = w[j];
        if (!inside(y[j], box[2 * v], box[2 * v + 1], false)) return false;
        if (!c_.periodic[v] && !c_.within_domain(v, y[j].lo(), y[j].hi())) return false;
        b[v] = y[j];
      }
      std::vector<Ival> g;
      if (!factors(b, g)) return false;
      for (int i = 0; i < c_.p; ++i)
        if (g[i].sign() != ((cls >> i) & 1 ? 1 : -1)) return false;
      // A feasible point: every constraint True on (u, H).
      if (!feasible(b)) return false;
      if (at) *at = y;
      return true;
    }
    for (int j = 0; j < n_; ++j) X[2 * j] = y[j].lo(), X[2 * j + 1] = y[j].hi();
    inflate(X);
  }
  return false;
}

// W_s ∩ box = ∅ by a paving of the chart's U: on each part, every zero of the cell's box
// has its w in W̃ (box_w ⊆ W̃) and so in W̃ ∩ y ∩ box_w (Hansen–Sengupta); a part is cleared
// when that is empty or a factor's enclosure over it excludes the class.
// b's w := an enclosure of w(u) for every u of b's u-part (the cell's chart): W̃ ∩ the chart's
// range, met with the step's images on b (up to six, while each halves it). False when that
// is empty: no solution of the chart over the part.
bool CountCheck::narrow_w(const Cell& cell, std::vector<Ival>& b) {
  const std::vector<int>& w = cell.w;
  for (int j = 0; j < n_; ++j) {
    b[w[j]].set(cell.w_tilde[2 * j], cell.w_tilde[2 * j + 1]);
    if (!b[w[j]].meet(cell.range[j])) return false;
  }
  std::vector<Ival> y;
  for (int sweep = 0; sweep < 6; ++sweep) {
    double before = 0, after = 0;
    for (int j = 0; j < n_; ++j) before += b[w[j]].hi() - b[w[j]].lo();
    const Hs h = hansen_sengupta(b, w, y);
    if (h == Hs::Empty) return false;
    if (h != Hs::Image) break;
    for (int j = 0; j < n_; ++j)
      if (!b[w[j]].meet(y[j])) return false;
    for (int j = 0; j < n_; ++j) after += b[w[j]].hi() - b[w[j]].lo();
    if (!(after < 0.5 * before)) break;
  }
  return true;
}

bool CountCheck::halve_widest_u(const Cell& cell, const std::vector<int>& uv, double min_rel,
                                Box z, std::vector<Box>& stack) const {
  int best = -1;
  double rel = min_rel;
  for (int v : uv) {
    const double full = cell.box[2 * v + 1] - cell.box[2 * v];
    const double r = (z[2 * v + 1] - z[2 * v]) / (full > 0 ? full : 1.0);
    if (r > rel) rel = r, best = v;
  }
  if (best < 0) return false;
  const double mid = 0.5 * (z[2 * best] + z[2 * best + 1]);
  if (!(z[2 * best] < mid && mid < z[2 * best + 1])) return false;
  Box right = z;
  z[2 * best + 1] = mid;
  right[2 * best] = mid;
  stack.push_back(std::move(z));
  stack.push_back(std::move(right));
  return true;
}

bool CountCheck::paving(const Cell& cell, Mask cls) {
  if (cell.w.empty()) return false;
  std::vector<int> uv;
  for (int v = 0; v < nv_; ++v)
    if (std::find(cell.w.begin(), cell.w.end(), v) == cell.w.end()) uv.push_back(v);
  std::vector<Box> stack{cell.box};
  long parts = 0;
  std::vector<Ival> y;
  while (!stack.empty()) {
    Box z = std::move(stack.back());
    stack.pop_back();
    if (++parts > kPavingParts) return false;
    std::vector<Ival> b = ivals(z);
    if (!narrow_w(cell, b)) continue;
    bool cleared = false;
    for (int j = 0; j < n_ && !cleared; ++j) {
      const int v = cell.w[j];
      Ival box_w;
      box_w.set(z[2 * v], z[2 * v + 1]);
      cleared = !b[v].meet(box_w);
    }
    if (!cleared) cleared = (excluded(b) >> cls) & 1;
    // No feasible point over the part: a constraint False on it.
    if (!cleared && !c_.m.constraints.empty()) cleared = c_.ev->feasible(b.data()) == 0;
    if (cleared) continue;
    if (!halve_widest_u(cell, uv, 1e-9, std::move(z), stack)) return false;
  }
  return true;
}

}  // namespace cc
