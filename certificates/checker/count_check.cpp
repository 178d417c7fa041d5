// count_check.cpp — trusted core: the records of a count certificate (FORMAT.md, "Count
// certificates"), after its search tree: how each box of the final cover came from the
// tree's output boxes (halves of bisections with their contractions, charts, boxes with no
// solution), what shows each piece empty or nonempty, the adjacencies refuted, and the
// claimed lower bound, recomputed from these alone. The proofs run in line, on the
// checker's own evaluator (after the tree's proofs are judged).
#include <map>

#include "check.h"

namespace cc {

namespace {

enum class Hs { Image, Empty, Failed };

// A class of sign vectors: bit i set when factor i is positive.
using Mask = uint64_t;
constexpr int kMaxCountFactors = 6;  // 2^6 classes, one bit each in a Mask

}  // namespace

class CountCheck {
 public:
  explicit CountCheck(Checker& c) : c_(c), pr_(*c.ev), n_(c.n), nv_(c.nv) {}
  void run();

 private:
  enum class State : uint8_t { Unmade, Pending, Live, Split, Void };
  struct Cell {
    State state = State::Unmade;
    Box origin, box;             // as created; now (after its chart)
    bool solution = false;       // made from an S record's output box
    std::vector<int> w;          // its chart (fit), for a paving or a star test
    Box w_tilde;
    std::vector<Ival> range;     // the chart's image: every w(u), u ∈ U, lies in it
    Mask claimed = 0;            // classes with a piece record
    Mask empty = 0, point = 0;   // verified: empty pieces, pieces holding a point of W_s
    Mask connected = 0;          // verified: connected pieces (nonempty: with a point too)
    Mask other_class = 0;        // empty because another class holds the graph (checked last)
    Mask graph_of_s = 0;         // connected as the graph of an S box, if nonempty (last)
  };

  Checker& c_;
  Prover pr_;
  int n_, nv_;
  long first_ = 0;
  long last_id_ = -1;
  std::vector<Cell> cells_;
  std::map<std::pair<long, long>, Mask> refuted_, joined_;  // verified, per pair of cells
  std::string upper_open_;  // why no upper bound, when none is proved
  // The star test's second derivatives: a copy of the model with the nodes of its Jacobian
  // (derivative.cpp), and an evaluator of them, made on first use.
  std::unique_ptr<Model> dm_;
  std::unique_ptr<Evaluator> dev_;
  std::vector<std::vector<int>> jn_;
  std::vector<int> jprog_;
  bool jn_ok_ = true;

  long rec() const { return c_.rec(); }
  [[noreturn]] void reject(const std::string& why) { c_.reject(why); }
  void limit() { c_.ev->work_limit = c_.work_limit(); }

  // ----- records
  long cell_id(bool order = true);
  Box reals_box(size_t k) { return c_.rd.intervals(k); }
  std::vector<int> chart_vars();
  Mask class_field();
  void half();
  void fit(bool void_only);
  void none();
  void split();
  void piece();
  void refuted();
  void joined();
  void every_cell_made();
  void finish();

  // ----- proofs
  Hs hansen_sengupta(std::vector<Ival>& box, const std::vector<int>& w, std::vector<Ival>& y);
  bool refute(const Box& b);
  bool no_class(std::vector<Ival> b, Mask cls, int depth, long& budget);
  bool factors(const std::vector<Ival>& box, std::vector<Ival>& out);
  Mask excluded(const Box& b);
  Mask excluded(const std::vector<Ival>& b);
  bool point(const Box& box, const std::vector<int>& w, const std::vector<double>& u,
             const Box& hint, Mask cls, std::vector<Ival>* at = nullptr);
  bool narrow_w(const Cell& cell, std::vector<Ival>& b);
  bool paving(const Cell& cell, Mask cls);
  bool crosses(const Cell& cell, int j, bool upper);
  bool graph(const Cell& cell, Mask cls);
  bool star(const Cell& cell, Mask cls, const std::vector<int>& w, const std::vector<double>& v,
            const Box& hint);
  bool factor_gradients(const std::vector<Ival>& b, std::vector<std::vector<Ival>>& grad);
  bool implicit_jacobian(const std::vector<Ival>& b, const std::vector<int>& w,
                         std::vector<Ival>& X);
  bool inside_root(const Box& b) const;
  long lower_bound();
  long upper_bound();

  std::vector<Ival> ivals(const Box& b) const {
    std::vector<Ival> out(b.size() / 2);
    for (size_t v = 0; v < out.size(); ++v) out[v].set(b[2 * v], b[2 * v + 1]);
    return out;
  }
};

void Checker::count_body() { CountCheck(*this).run(); }

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
    if (++parts > 4096) return false;
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
    if (cleared) continue;
    int best = -1;
    double rel = 1e-9;
    for (int k = 0; k < n_; ++k) {
      const int v = uv[k];
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
  }
  return true;
}

// ---------------------------------------------------------------- records

// The cell a record is about: an id below the announced number, records in id order.
long CountCheck::cell_id(bool order) {
  const long id = c_.index(cells_.size());
  if (order) {
    if (id < last_id_) reject("count records are not in cell order");
    last_id_ = id;
    if (cells_[id].state == State::Pending) reject("a half's first record must be 'half'");
    if (cells_[id].state == State::Unmade) reject("no such cell yet");
  }
  return id;
}

std::vector<int> CountCheck::chart_vars() {
  std::vector<int> w(n_);
  for (int j = 0; j < n_; ++j) {
    w[j] = int(c_.index(nv_));
    for (int k = 0; k < j; ++k)
      if (w[k] == w[j]) reject("a chart names a variable twice");
  }
  return w;
}

Mask CountCheck::class_field() {
  const std::string_view s = c_.rd.word();
  if (!c_.well_formed(s) || s.find('0') != s.npos) malformed(rec(), "bad class '" + std::string(s) + "'");
  Mask cls = 0;
  for (int i = 0; i < c_.p; ++i)
    if (s[i] == '+') cls |= Mask(1) << i;
  return cls;
}

// half ID BOX: the box of a half its parent's split left pending, contracted: the closed
// slabs between them hold no solution (refuted as a contraction record's are).
void CountCheck::half() {
  c_.rd.count(2 + 2 * size_t(nv_));
  const long id = c_.index(cells_.size());
  if (id < last_id_) reject("count records are not in cell order");
  last_id_ = id;
  Cell& cell = cells_[id];
  if (cell.state != State::Pending) reject("no split left this cell pending");
  const Box b = reals_box(nv_);
  Box cur = cell.origin;
  for (int v = 0; v < nv_; ++v) {
    const double lo = cur[2 * v], hi = cur[2 * v + 1];
    if (!within(lo, hi, b[2 * v], b[2 * v + 1])) reject("the half's box is not inside the half");
    Box slab = cur;
    put(slab, v, lo, b[2 * v]);
    if (b[2 * v] > lo && !refute(slab)) reject("cannot refute the slab below the half's box" + c_.show(slab));
    put(slab, v, b[2 * v + 1], hi);
    if (b[2 * v + 1] < hi && !refute(slab)) reject("cannot refute the slab above the half's box" + c_.show(slab));
    put(cur, v, b[2 * v], b[2 * v + 1]);
  }
  cell.origin = cell.box = b;
  cell.state = State::Live;
}

// fit ID W W~ BOX: the chart's iterate W̃ holds the origin's w; Hansen–Sengupta on
// origin_u × W̃ gives H ⊆ int W̃, so every solution of the origin is (u, w(u)) with w(u) ∈
// origin_w ∩ H (∩ the domain's enclosure on a non-periodic w), which BOX holds; BOX keeps
// the origin's u and lies in W̃ (so V ∩ BOX is the graph over U cut by BOX's w).
// void ID W W~: the same step shows no solution in the origin.
void CountCheck::fit(bool void_only) {
  c_.rd.count(2 + size_t(n_) + 2 * size_t(n_) + (void_only ? 0 : 2 * size_t(nv_)));
  const long id = cell_id();
  Cell& cell = cells_[id];
  if (cell.state != State::Live || cell.box != cell.origin || cell.claimed)
    reject("a chart record must follow the cell's creation");
  const std::vector<int> w = chart_vars();
  const Box wt = reals_box(n_);
  const Box B = void_only ? Box() : reals_box(nv_);
  std::vector<Ival> b = ivals(cell.origin);
  for (int j = 0; j < n_; ++j) {
    const int v = w[j];
    if (!within(wt[2 * j], wt[2 * j + 1], cell.origin[2 * v], cell.origin[2 * v + 1]))
      reject("the chart's W~ does not hold the box's " + c_.m.vars[v].name);
    b[v].set(wt[2 * j], wt[2 * j + 1]);
  }
  std::vector<Ival> y;
  const Hs h = hansen_sengupta(b, w, y);
  if (void_only) {
    bool none = h == Hs::Empty;
    for (int j = 0; j < n_ && h == Hs::Image && !none; ++j) {
      const int v = w[j];
      Ival o;
      o.set(cell.origin[2 * v], cell.origin[2 * v + 1]);
      Ival yj = y[j];
      none = !yj.meet(o) || (!c_.periodic[v] && !yj.meet([&] {
                               Ival d;
                               d.set(c_.root[2 * v], c_.root[2 * v + 1]);
                               return d;
                             }()));
    }
    if (!none) reject("void: the chart does not show the box empty" + c_.show(cell.origin));
    cell.state = State::Void;
    return;
  }
  if (h != Hs::Image) reject("chart: Hansen-Sengupta fails on the box" + c_.show(cell.origin));
  for (int j = 0; j < n_; ++j)
    if (!inside(y[j], wt[2 * j], wt[2 * j + 1], true))
      reject("chart: the Hansen-Sengupta image is not inside the interior of W~");
  // The origin's solutions lie in W̃ ∩ y; the same step on origin_u × (W̃ ∩ y) encloses them
  // again, often more tightly than one step (whose image the solver's box may have met
  // with the origin's w, with ends a rounding apart from this one's).
  bool no_zero = false;
  for (int it = 0; it < 3 && !no_zero; ++it) {
    for (int j = 0; j < n_; ++j) b[w[j]] = y[j];
    std::vector<Ival> y2;
    const Hs again = hansen_sengupta(b, w, y2);
    if (again == Hs::Empty) no_zero = true;
    if (again != Hs::Image) break;
    for (int j = 0; j < n_ && !no_zero; ++j) no_zero = !y[j].meet(y2[j]);
  }
  for (int v = 0; v < nv_; ++v) {
    const auto it = std::find(w.begin(), w.end(), v);
    if (it == w.end()) {
      if (B[2 * v] != cell.origin[2 * v] || B[2 * v + 1] != cell.origin[2 * v + 1])
        reject("chart: the box's u changed");
      continue;
    }
    const size_t j = size_t(it - w.begin());
    if (!within(wt[2 * j], wt[2 * j + 1], B[2 * v], B[2 * v + 1]))
      reject("chart: the box's " + c_.m.vars[v].name + " leaves W~");
    // B_v ⊇ origin_v ∩ H_j (∩ the root cell's v if it is not periodic): each end of the
    // meet is one of the ends it is the max (min) of.
    const bool dom = !c_.periodic[v];
    bool lo_ok = B[2 * v] <= cell.origin[2 * v] || cmp(y[j], Lo, B[2 * v]) >= 0 ||
                 (dom && B[2 * v] <= c_.root[2 * v]);
    bool hi_ok = B[2 * v + 1] >= cell.origin[2 * v + 1] || cmp(y[j], Hi, B[2 * v + 1]) <= 0 ||
                 (dom && B[2 * v + 1] >= c_.root[2 * v + 1]);
    // Else the solver's image and this one differ at that end in the last bits: the closed
    // slab of the origin beyond BOX's end is refuted instead (it holds no solution).
    Box slab = cell.origin;
    if (!lo_ok && B[2 * v] <= cell.origin[2 * v + 1]) {
      put(slab, v, cell.origin[2 * v], B[2 * v]);
      lo_ok = refute(slab);
    }
    slab = cell.origin;
    if (!hi_ok && B[2 * v + 1] >= cell.origin[2 * v]) {
      put(slab, v, B[2 * v + 1], cell.origin[2 * v + 1]);
      hi_ok = refute(slab);
    }
    // An empty meet: the origin holds no solution, any box will do.
    const bool empty_meet = cmp(y[j], Lo, cell.origin[2 * v + 1]) > 0 ||
                            cmp(y[j], Hi, cell.origin[2 * v]) < 0;
    if (!(lo_ok && hi_ok) && !empty_meet && !no_zero)
      reject("chart: the box does not hold the origin's solutions in " + c_.m.vars[v].name);
  }
  cell.box = B;
  cell.w = w;
  cell.w_tilde = wt;
  cell.range = y;
}

// none ID: the origin holds no solution (refuted).
void CountCheck::none() {
  c_.rd.count(2);
  const long id = cell_id();
  Cell& cell = cells_[id];
  if (cell.state != State::Live || cell.box != cell.origin || cell.claimed)
    reject("a 'none' record must follow the cell's creation");
  if (!refute(cell.origin)) reject("cannot refute the box" + c_.show(cell.origin));
  cell.state = State::Void;
}

// split ID V X L R: the cell's box cut at X on V into closed halves; a half is the new
// cell L (R), or -1: refuted.
void CountCheck::split() {
  c_.rd.count(6);
  const long id = cell_id();
  Cell& cell = cells_[id];
  if (cell.state != State::Live || cell.claimed) reject("split of a cell that is not live");
  const long v = c_.index(nv_);
  const double x = c_.rd.real();
  if (!(cell.box[2 * v] < x && x < cell.box[2 * v + 1]))
    reject("split point not strictly inside the box");
  for (int side = 0; side < 2; ++side) {
    const int64_t child = c_.rd.integer();
    Box h = cell.box;
    h[2 * v + (side == 0 ? 1 : 0)] = x;
    if (child == -1) {
      if (!refute(h)) reject("cannot refute the discarded half" + c_.show(h));
      continue;
    }
    if (child <= id || child >= int64_t(cells_.size()) ||
        cells_[child].state != State::Unmade)
      reject("a split's half must be a new cell of a larger id");
    cells_[child].state = State::Pending;
    cells_[child].origin = cells_[child].box = h;
  }
  cell.state = State::Split;
}

// piece ID CLASS STATE PROOF.
void CountCheck::piece() {
  const long id = cell_id();
  Cell& cell = cells_[id];
  if (cell.state != State::Live && cell.state != State::Void)
    reject("a piece of a cell that is not in the final cover");
  const Mask cls = class_field();
  if ((cell.claimed >> cls) & 1) reject("two piece records of one class");
  cell.claimed |= Mask(1) << cls;
  const std::string state(c_.rd.word());
  const std::string proof(c_.rd.word());
  if (state == "empty") {
    c_.rd.count(5);
    if (proof == "void") {
      if (cell.state != State::Void) reject("empty by void: the cell is not shown empty");
    } else if (proof == "signs") {
      if (!(((excluded(cell.box) | excluded(cell.origin)) >> cls) & 1))
        reject("empty by signs: no factor's enclosure excludes the class" + c_.show(cell.box));
    } else if (proof == "paving") {
      if (!paving(cell, cls)) reject("empty by paving: a part could not be cleared" + c_.show(cell.box));
    } else if (proof == "other-class") {
      cell.other_class |= Mask(1) << cls;  // checked once every piece is read
    } else {
      malformed(rec(), "unknown proof of an empty piece '" + proof + "'");
    }
    cell.empty |= Mask(1) << cls;
    return;
  }
  if (state != "connected" && state != "nonempty" && state != "undecided")
    malformed(rec(), "unknown piece state '" + state + "'");
  // `proof` is how the piece is connected: graph, star, or `-` when it is not claimed.
  const bool connected = state == "connected";
  if (connected ? proof != "graph" && proof != "star" : proof != "-")
    malformed(rec(), "bad connectedness field '" + proof + "'");
  const std::string with(c_.rd.word());
  if (with == "-") {
    c_.rd.count(6);
    if (proof == "star") malformed(rec(), "a star test needs its centre");
  } else {
    if (with != "point" || state == "undecided") malformed(rec(), "bad point field '" + with + "'");
    c_.rd.count(6 + 4 * size_t(n_));
  }
  std::vector<int> w;
  std::vector<double> u;
  Box hint;
  if (with == "point") {
    w = chart_vars();
    u = c_.rd.reals(n_);
    hint = reals_box(n_);
    if (cell.state == State::Void) reject("a point in a cell shown empty");
    if (!point(cell.box, w, u, hint, cls))
      reject("point: no zero of the class proved at the u-point" + c_.show(cell.box));
    cell.point |= Mask(1) << cls;
  }
  if (proof == "graph") {
    if (cell.solution && cell.box == cell.origin && cell.w.empty()) {
      cell.graph_of_s |= Mask(1) << cls;  // judged once every piece of the cell is read
    } else {
      if (!graph(cell, cls))
        reject("connected: the box is not the graph of its chart in one class" + c_.show(cell.box));
      cell.connected |= Mask(1) << cls;
    }
  } else if (proof == "star") {
    if (!star(cell, cls, w, u, hint))
      reject("connected: the star-shaped test fails about the centre" + c_.show(cell.box));
    cell.connected |= Mask(1) << cls;
  }
}

// refuted A B CLASS: for every shift under which the closed boxes meet, their closed
// intersection holds no solution, or a factor's enclosure on it excludes the class.
void CountCheck::refuted() {
  c_.rd.count(4);
  const long a = c_.index(cells_.size());
  const long b = c_.index(cells_.size());
  const Mask cls = class_field();
  if (!(a < b)) reject("refuted needs A < B");
  for (long x : {a, b})
    if (cells_[x].state != State::Live && cells_[x].state != State::Void)
      reject("refuted: a cell that is not in the final cover");
  std::vector<int> per;
  for (int v = 0; v < nv_; ++v)
    if (c_.periodic[v]) per.push_back(v);
  if (per.size() > 12) reject("refuted: too many periodic variables");
  std::vector<int> k(nv_, 0);
  for (long code = 0; code < std::lround(std::pow(3, per.size())); ++code) {
    long r = code;
    for (int v : per) k[v] = int(r % 3) - 1, r /= 3;
    Box I(2 * nv_);
    bool meet = true;
    Ival t;
    for (int v = 0; v < nv_ && meet; ++v) {
      double lo = cells_[b].box[2 * v], hi = cells_[b].box[2 * v + 1];
      if (k[v]) {
        shift_by_periods(t, c_.ev->two_pi, k[v], lo);
        lo = t.lo();
        shift_by_periods(t, c_.ev->two_pi, k[v], hi);
        hi = t.hi();
      }
      lo = std::max(lo, cells_[a].box[2 * v]);
      hi = std::min(hi, cells_[a].box[2 * v + 1]);
      meet = lo <= hi;
      put(I, v, lo, hi);
    }
    if (!meet) continue;
    long budget = 1024;
    if (!no_class(ivals(I), cls, 0, budget))
      reject("refuted: cannot show the boxes' intersection free of the class" + c_.show(I));
  }
  refuted_[{a, b}] |= Mask(1) << cls;
}

// Empty by another class: an S record's box, unchanged, is the graph of q over its pose box
// (P1), on which det Fx and det Fq do not vanish (P2): connected, so in one class; a point
// of another class shows which.
void CountCheck::finish() {
  for (Cell& cell : cells_) {
    if (!cell.other_class) continue;
    if (!cell.solution || cell.state != State::Live || !cell.w.empty() || cell.box != cell.origin)
      reject("empty by another class: the cell is not a solution box");
    if (!(cell.point & ~cell.other_class)) reject("empty by another class: no point of another class");
  }
  // Connected as an S box's graph (P1, P2): in one class, s, when all factors have its sign
  // on the box or a point of s is verified in it.
  for (Cell& cell : cells_) {
    if (!cell.graph_of_s) continue;
    std::vector<Ival> g;
    Mask certain = 0;
    if (factors(ivals(cell.box), g)) {
      Mask cls = 0;
      bool all = true;
      for (int i = 0; i < c_.p; ++i) {
        all = all && g[i].sign() != 0;
        if (g[i].sign() > 0) cls |= Mask(1) << i;
      }
      if (all) certain = Mask(1) << cls;
    }
    if (cell.graph_of_s & ~(cell.point | certain))
      reject("connected: an S box's piece with neither a point nor every sign of its class");
    cell.connected |= cell.graph_of_s;
  }
}

// The graph G of FORMAT.md (C1): per class, the pieces not shown empty, joined on every
// pair of M (the final cover's boxes) not refuted in that class; a component counts when
// it holds a piece shown nonempty (a point, or an S box whose factors all have a sign).
long CountCheck::lower_bound() {
  std::vector<long> ids;
  OutBoxes F;
  F.nv = nv_;
  std::vector<Mask> nodes, nonempty;
  const Mask all = (c_.p >= 6 ? ~Mask(0) : (Mask(1) << (Mask(1) << c_.p)) - 1);
  for (size_t id = 0; id < cells_.size(); ++id) {
    const Cell& cell = cells_[id];
    if (cell.state != State::Live) continue;
    ids.push_back(long(id));
    F.add_box(cell.box.data());
    F.pos.push_back(0), F.neg.push_back(0), F.solution.push_back(cell.solution);
    Mask ne = cell.point;
    const Mask ex = excluded(cell.box) | excluded(cell.origin);
    if (cell.solution && cell.box == cell.origin) {
      std::vector<Ival> g;
      Mask cls = 0;
      bool all_signs = factors(ivals(cell.box), g);
      for (int i = 0; all_signs && i < c_.p; ++i) {
        all_signs = g[i].sign() != 0;
        if (g[i].sign() > 0) cls |= Mask(1) << i;
      }
      if (all_signs) ne |= Mask(1) << cls;
    }
    nodes.push_back(all & ~ex & ~cell.empty);
    nonempty.push_back(ne & all & ~ex & ~cell.empty);
  }
  const size_t m = ids.size();
  const int classes = 1 << c_.p;
  std::vector<UnionFind> uf(classes);
  for (UnionFind& u : uf) u.reset(m);
  PlainSweep M(F, c_.periodic, c_.ev->two_pi);
  try {
    M.run([&](int i, int j) {
    const long a = std::min(ids[i], ids[j]), b = std::max(ids[i], ids[j]);
    auto r = refuted_.find({a, b});
    const Mask cut = r == refuted_.end() ? 0 : r->second;
    const Mask both = nodes[i] & nodes[j] & ~cut;
    for (int s = 0; s < classes; ++s)
      if ((both >> s) & 1) uf[s].unite(i, j);
    }, (size_t(1) << 22) + 64 * m);
  } catch (const std::length_error&) {
    reject("the neighbourhood graph has more than 2^22 + 64 pairs per box");
  }
  long bound = 0;
  for (int s = 0; s < classes; ++s) {
    std::vector<uint8_t> counted(m, 0);
    for (size_t i = 0; i < m; ++i) {
      if (!((nonempty[i] >> s) & 1)) continue;
      const int root = uf[s].find(int(i));
      if (!counted[root]) counted[root] = 1, ++bound;
    }
  }
  return bound;
}


// ---------------------------------------------------------------- connected pieces and joins

// Non-periodic variables of b lie in the root cell (V ∩ b is then the graph itself, not a
// part of it outside D).
bool CountCheck::inside_root(const Box& b) const {
  for (int v = 0; v < nv_; ++v)
    if (!c_.periodic[v] && !within(c_.root[2 * v], c_.root[2 * v + 1], b[2 * v], b[2 * v + 1]))
      return false;
  return true;
}

// The graph of the cell's chart may cross the lower (upper) face of its box's w_j: the chart's
// image reaches beyond it, and the closed slab of U × (W̃ ∩ image) beyond the face is not
// refuted (the solver's image and the checker's differ in the last bits at such an end).
bool CountCheck::crosses(const Cell& cell, int j, bool upper) {
  const int v = cell.w[j];
  const double face = cell.box[2 * v + upper];
  if (upper ? cmp(cell.range[j], Hi, face) <= 0 : cmp(cell.range[j], Lo, face) >= 0) return false;
  Box slab = cell.box;
  for (int k = 0; k < n_; ++k) {
    Ival x;
    x.set(cell.w_tilde[2 * k], cell.w_tilde[2 * k + 1]);
    if (!x.meet(cell.range[k])) return false;  // no solution at all
    put(slab, cell.w[k], x.lo(), x.hi());
  }
  if (upper ? face >= slab[2 * v + 1] : face <= slab[2 * v]) return true;
  if (upper) slab[2 * v] = face;
  else slab[2 * v + 1] = face;
  return !refute(slab);
}

// A fit's box whose chart's image lies in its w, inside the root cell, every factor of the
// class's sign on it: W_s ∩ box = V ∩ box is the graph of the continuous w over U, connected
// and nonempty.
bool CountCheck::graph(const Cell& cell, Mask cls) {
  if (cell.w.empty() || !inside_root(cell.box)) return false;
  for (int j = 0; j < n_; ++j)
    if (crosses(cell, j, false) || crosses(cell, j, true)) return false;
  std::vector<Ival> g;
  if (!factors(ivals(cell.box), g)) return false;
  for (int i = 0; i < c_.p; ++i)
    if (g[i].sign() != ((cls >> i) & 1 ? 1 : -1)) return false;
  return true;
}

// ∂g_i/∂x_v for every factor i over b, from the Jacobian's nodes and their AD: for a
// determinant, Σ_r det(J with row r replaced by ∂J_r/∂x_v) (Jacobi's formula).
bool CountCheck::factor_gradients(const std::vector<Ival>& b,
                                  std::vector<std::vector<Ival>>& grad) {
  if (!dm_) {
    dm_.reset(new Model(c_.m));
    jn_ = jacobian_nodes(*dm_);
    std::vector<int> roots;
    for (const auto& row : jn_)
      for (int e : row) {
        if (e < 0) jn_ok_ = false;
        else roots.push_back(e);
      }
    jprog_ = closure(*dm_, roots);
    dev_.reset(new Evaluator(*dm_));
  }
  if (!jn_ok_) return false;
  dev_->work_limit = c_.work_limit();
  if (!dev_->eval_ad(jprog_, b.data(), ~uint64_t(0) >> (64 - nv_))) return false;
  const int n = n_;
  grad.assign(c_.p, std::vector<Ival>(nv_));
  std::vector<Ival> M(size_t(n) * n);
  for (int i = 0; i < c_.p; ++i) {
    const Factor& f = c_.factors[i];
    const bool fx = f.kind == Factor::DetFx || f.kind == Factor::DiagFx;
    const std::vector<int>& cols = fx ? c_.m.pose : c_.m.command;
    for (int t = 0; t < nv_; ++t) {
      if (f.kind == Factor::DiagFx || f.kind == Factor::DiagFq) {
        grad[i][t] = dev_->der(jn_[f.arg][cols[f.arg]], t);
        continue;
      }
      set_si(grad[i][t], 0);
      Ival term;
      for (int r = 0; r < n; ++r) {
        for (int a = 0; a < n; ++a)
          for (int c = 0; c < n; ++c)
            M[a * n + c] = a == r ? dev_->der(jn_[a][cols[c]], t) : dev_->val(jn_[a][cols[c]]);
        det(M, n, term);
        add(grad[i][t], grad[i][t], term);
      }
      if (!grad[i][t].bounded()) return false;
    }
  }
  return true;
}

// X = (∂_w f)^{-1} ∂_u f over b (n×n, row major; dw/du = −X), by a verified solve: with C
// an approximate inverse of mid ∂_w f, A = C·∂_w f, B = C·∂_u f, E = I − A and β = ‖E‖_∞ < 1,
// every point of b has X = B + E·X, so ‖X_{·k}‖_∞ ≤ ρ_k = max_l |B_lk| / (1 − β) and X_jk ∈
// B_jk + Σ_l E_jl·[−ρ_k, ρ_k]. β < 1 also proves ∂_w f regular on b (w is C¹ there).
bool CountCheck::implicit_jacobian(const std::vector<Ival>& b, const std::vector<int>& w,
                                   std::vector<Ival>& X) {
  Evaluator& ev = *c_.ev;
  const int n = n_;
  std::vector<int> u;
  for (int v = 0; v < nv_; ++v)
    if (std::find(w.begin(), w.end(), v) == w.end()) u.push_back(v);
  limit();
  if (!ev.eval_ad(ev.all_eqs, b.data(), ~uint64_t(0) >> (64 - nv_))) return false;
  std::vector<double> M(size_t(n) * n), C;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Ival& d = ev.der(c_.m.eqs[i], w[j]);
      M[i * n + j] = 0.5 * (d.lo() + d.hi());
    }
  if (!invert(M, n, C)) return false;
  std::vector<Ival> E(size_t(n) * n), B(size_t(n) * n);
  Ival t, beta, row;
  set_si(beta, 0);
  for (int i = 0; i < n; ++i) {
    set_si(row, 0);
    for (int j = 0; j < n; ++j) {
      set_si(E[i * n + j], i == j ? 1 : 0);
      set_si(B[i * n + j], 0);
      for (int k = 0; k < n; ++k) {
        mul_d(t, ev.der(c_.m.eqs[k], w[j]), C[i * n + k]);
        sub(E[i * n + j], E[i * n + j], t);
        mul_d(t, ev.der(c_.m.eqs[k], u[j]), C[i * n + k]);
        add(B[i * n + j], B[i * n + j], t);
      }
      abs(t, E[i * n + j]);
      add(row, row, t);
    }
    max(beta, beta, row);
  }
  Ival gap;  // 1 − β
  si_sub(gap, 1, beta);
  if (gap.sign() <= 0) return false;
  X.resize(size_t(n) * n);
  for (int k = 0; k < n; ++k) {
    Ival rho;
    set_si(rho, 0);
    for (int l = 0; l < n; ++l) {
      abs(t, B[l * n + k]);
      max(rho, rho, t);
    }
    div(rho, rho, gap);
    Ival r;
    r.set(-rho.hi(), rho.hi());
    for (int j = 0; j < n; ++j) {
      X[j * n + k] = B[j * n + k];
      for (int l = 0; l < n; ++l) {
        mul(t, E[j * n + l], r);
        add(X[j * n + k], X[j * n + k], t);
      }
      if (!X[j * n + k].bounded()) return false;
    }
  }
  return true;
}

// The star-shaped test (FORMAT.md C4) about the centre v, on the cell's chart: the piece is
// {u ∈ U : φ_i(u) = s_i g_i(u, w(u)) > 0 for the factors not of sign s_i on the whole box,
// ψ(u) ≥ 0 for the faces of the box's w that the chart's image crosses}. The checker paves U
// itself: a part is cleared when a constraint is certainly < 0 on it, or when every
// constraint that case (i) or (ii) needs is certainly > 0 there or has ∇·(part − v)
// certainly < 0; else it is halved (widest u relative to the box, down to 10^-6 of it, at
// most 8192 parts).
bool CountCheck::star(const Cell& cell, Mask cls, const std::vector<int>& w,
                      const std::vector<double>& v, const Box& hint) {
  if (cell.w.empty() || w != cell.w || !inside_root(cell.box)) return false;
  std::vector<int> uv;
  for (int x = 0; x < nv_; ++x)
    if (std::find(w.begin(), w.end(), x) == w.end()) uv.push_back(x);
  struct Constraint {
    int kind;  // 0 factor, 1 lower face, 2 upper face
    int index;
  };
  std::vector<Constraint> cs;
  std::vector<Ival> g;
  const bool on_box = factors(ivals(cell.box), g);
  for (int i = 0; i < c_.p; ++i)
    if (!on_box || g[i].sign() != ((cls >> i) & 1 ? 1 : -1)) cs.push_back({0, i});
  for (int j = 0; j < n_; ++j) {
    if (crosses(cell, j, false)) cs.push_back({1, j});
    if (crosses(cell, j, true)) cs.push_back({2, j});
  }
  // The centre: a point of the piece with every constraint > 0 there.
  std::vector<Ival> wv;
  if (!point(cell.box, w, v, hint, cls, &wv)) return false;
  for (const Constraint& c : cs) {
    const int x = c.kind ? w[c.index] : 0;
    if (c.kind == 1 && cmp(wv[c.index], Lo, cell.box[2 * x]) <= 0) return false;
    if (c.kind == 2 && cmp(wv[c.index], Hi, cell.box[2 * x + 1]) >= 0) return false;
  }
  std::vector<Box> stack{cell.box};
  long parts = 0;
  std::vector<Ival> y, X, psi(cs.size());
  std::vector<std::vector<Ival>> grad;
  Ival t, d;
  while (!stack.empty()) {
    Box z = std::move(stack.back());
    stack.pop_back();
    if (++parts > 8192) return false;
    // w over the part: in W̃ (unique) and in every image of the step on part × (W̃ ∩ ...).
    std::vector<Ival> b = ivals(z);
    if (!narrow_w(cell, b)) continue;  // no point of the graph over this part
    const bool defined = factors(b, g);
    bool negative = false, strict_can_be_positive = true;
    for (size_t k = 0; k < cs.size(); ++k) {
      const Constraint& c = cs[k];
      if (c.kind == 0) {
        if (!defined) {
          psi[k].entire();
          continue;
        }
        psi[k] = g[c.index];
        if (!((cls >> c.index) & 1)) neg(psi[k], psi[k]);
        if (psi[k].end_sign(Hi) <= 0) strict_can_be_positive = false;
      } else {
        const double bound = cell.box[2 * w[c.index] + (c.kind == 2)];
        t.set(bound, bound);
        if (c.kind == 1) sub(psi[k], b[w[c.index]], t);
        else sub(psi[k], t, b[w[c.index]]);
      }
      negative = negative || psi[k].sign() < 0;
    }
    if (negative) continue;
    bool cleared = true, have_x = false, x_ok = false, have_g = false, g_ok = false;
    for (size_t k = 0; k < cs.size() && cleared; ++k) {
      const Constraint& c = cs[k];
      if (c.kind && !strict_can_be_positive) continue;  // case (ii) impossible here
      if (psi[k].sign() > 0) continue;                  // ≠ 0 on the part
      if (!have_x) have_x = true, x_ok = implicit_jacobian(b, w, X);
      cleared = false;
      if (!x_ok) break;
      std::vector<Ival> gr(n_);
      if (c.kind == 0) {
        if (!have_g) have_g = true, g_ok = factor_gradients(b, grad);
        if (!g_ok) break;
        const bool positive = (cls >> c.index) & 1;
        for (int k2 = 0; k2 < n_; ++k2) {  // ∂_u g − ∂_w g·X, times s_i
          gr[k2] = grad[c.index][uv[k2]];
          for (int j = 0; j < n_; ++j) {
            mul(t, grad[c.index][w[j]], X[j * n_ + k2]);
            sub(gr[k2], gr[k2], t);
          }
          if (!positive) neg(gr[k2], gr[k2]);
        }
      } else {
        for (int k2 = 0; k2 < n_; ++k2) {  // ∇w_j = −X_j·
          gr[k2] = X[c.index * n_ + k2];
          if (c.kind == 1) neg(gr[k2], gr[k2]);
        }
      }
      set_si(d, 0);
      for (int k2 = 0; k2 < n_; ++k2) {
        t.set(v[k2], v[k2]);
        Ival du;
        sub(du, b[uv[k2]], t);
        mul(t, gr[k2], du);
        add(d, d, t);
      }
      cleared = d.sign() < 0;
    }
    if (cleared) continue;
    int best = -1;
    double rel = 1e-6;
    for (int k = 0; k < n_; ++k) {
      const int x = uv[k];
      const double full = cell.box[2 * x + 1] - cell.box[2 * x];
      const double r = (z[2 * x + 1] - z[2 * x]) / (full > 0 ? full : 1.0);
      if (r > rel) rel = r, best = x;
    }
    if (best < 0) return false;
    const double mid = 0.5 * (z[2 * best] + z[2 * best + 1]);
    if (!(z[2 * best] < mid && mid < z[2 * best + 1])) return false;
    Box right = z;
    z[2 * best + 1] = mid;
    right[2 * best] = mid;
    stack.push_back(std::move(z));
    stack.push_back(std::move(right));
  }
  return true;
}

// joined A B CLASS SHIFT point W U HINT | bridge W W~: a point of W_s in A ∩ (B + 2πk)
// (the ends of B + 2πk rounded inward), or a bridge: with C the hull of A and B + 2πk (ends
// rounded outward), the step on C_u × W̃ (W̃ ⊇ C_w) has its image H in int W̃ and, on a
// non-periodic w, in the root cell, and every factor has the class's sign on C_u × H: V ∩ C
// is then the graph of w over C_u ∩ the root, connected, in W_s, holding both pieces.
void CountCheck::joined() {
  const long a = c_.index(cells_.size());
  const long b = c_.index(cells_.size());
  const Mask cls = class_field();
  if (!(a < b)) reject("joined needs A < B");
  for (long x : {a, b})
    if (cells_[x].state != State::Live) reject("joined: a cell that is not in the final cover");
  const std::string_view shift = c_.rd.word();
  if (shift.size() != size_t(nv_) || shift.find_first_not_of("-0+") != shift.npos)
    malformed(rec(), "bad SHIFT field");
  const std::string how(c_.rd.word());
  if (how == "point") c_.rd.count(6 + 4 * size_t(n_));
  else if (how == "bridge") c_.rd.count(6 + 3 * size_t(n_));
  else malformed(rec(), "joined: unknown proof '" + how + "'");
  const std::vector<int> w = chart_vars();
  Box inner = cells_[a].box, hull = cells_[a].box;
  Ival t;
  for (int v = 0; v < nv_; ++v) {
    const int k = shift[v] == '-' ? -1 : shift[v] == '+' ? 1 : 0;
    if (k && !c_.periodic[v]) reject("joined: a shift on a variable that is not periodic");
    double lo = cells_[b].box[2 * v], hi = cells_[b].box[2 * v + 1];
    double ilo = lo, ihi = hi, olo = lo, ohi = hi;
    if (k) {
      shift_by_periods(t, c_.ev->two_pi, k, lo);
      ilo = t.hi(), olo = t.lo();
      shift_by_periods(t, c_.ev->two_pi, k, hi);
      ihi = t.lo(), ohi = t.hi();
    }
    put(inner, v, std::max(inner[2 * v], ilo), std::min(inner[2 * v + 1], ihi));
    put(hull, v, std::min(hull[2 * v], olo), std::max(hull[2 * v + 1], ohi));
  }
  if (how == "point") {
    const std::vector<double> u = c_.rd.reals(n_);
    const Box hint = reals_box(n_);
    for (int v = 0; v < nv_; ++v)
      if (!(inner[2 * v] <= inner[2 * v + 1])) reject("joined: the boxes do not meet");
    if (!point(inner, w, u, hint, cls)) reject("joined: no point of the class proved in both boxes");
  } else {
    const Box wt = reals_box(n_);
    std::vector<Ival> box = ivals(hull), y;
    for (int j = 0; j < n_; ++j) {
      const int v = w[j];
      if (!within(wt[2 * j], wt[2 * j + 1], hull[2 * v], hull[2 * v + 1]))
        reject("joined: the bridge's W~ does not hold the hull");
      box[v].set(wt[2 * j], wt[2 * j + 1]);
    }
    if (hansen_sengupta(box, w, y) != Hs::Image) reject("joined: the bridge's chart fails");
    for (int j = 0; j < n_; ++j) {
      const int v = w[j];
      if (!inside(y[j], wt[2 * j], wt[2 * j + 1], true))
        reject("joined: the bridge's image is not inside the interior of W~");
      if (!c_.periodic[v] && !inside(y[j], c_.root[2 * v], c_.root[2 * v + 1], false))
        reject("joined: the bridge's graph leaves the domain");
      box[v] = y[j];
    }
    std::vector<Ival> g;
    if (!factors(box, g)) reject("joined: a factor is not defined on the bridge");
    for (int i = 0; i < c_.p; ++i)
      if (g[i].sign() != ((cls >> i) & 1 ? 1 : -1))
        reject("joined: a factor's sign on the bridge is not the class's");
  }
  joined_[{a, b}] |= Mask(1) << cls;
}

// The graph H of FORMAT.md (C6): per class, the same nodes as the lower bound's, joined by the
// verified joins. −1 unless every node's piece is proved connected.
long CountCheck::upper_bound() {
  const int classes = 1 << c_.p;
  std::vector<long> index(cells_.size(), -1);
  std::vector<Mask> nodes;
  long m = 0;
  for (size_t id = 0; id < cells_.size(); ++id) {
    const Cell& cell = cells_[id];
    if (cell.state != State::Live) continue;
    index[id] = m++;
    const Mask all = (c_.p >= 6 ? ~Mask(0) : (Mask(1) << classes) - 1);
    const Mask node = all & ~(excluded(cell.box) | excluded(cell.origin)) & ~cell.empty;
    if (node & ~cell.connected) {
      for (int s = 0; s < classes; ++s)
        if ((node & ~cell.connected) >> s & 1)
          upper_open_ = "the piece of class " + std::to_string(s) + " of cell " +
                        std::to_string(id) + " is not proved connected";
      return -1;
    }
    nodes.push_back(node);
  }
  std::vector<UnionFind> uf(classes);
  for (UnionFind& u : uf) u.reset(size_t(m));
  for (const auto& e : joined_)
    for (int s = 0; s < classes; ++s)
      if ((e.second >> s & 1) && (nodes[index[e.first.first]] >> s & 1) &&
          (nodes[index[e.first.second]] >> s & 1))
        uf[s].unite(int(index[e.first.first]), int(index[e.first.second]));
  long bound = 0;
  for (int s = 0; s < classes; ++s)
    for (long i = 0; i < m; ++i)
      if ((nodes[i] >> s & 1) && uf[s].find(int(i)) == int(i)) ++bound;
  return bound;
}

void CountCheck::every_cell_made() {
  for (const Cell& cell : cells_)
    if (cell.state == State::Unmade || cell.state == State::Pending)
      reject("count: a cell announced is never made, or a half never given its box");
}

void CountCheck::run() {
  if (c_.p > kMaxCountFactors) reject("a count certificate has at most 6 factors");
  for (const Factor& f : c_.factors)
    if (f.kind == Factor::User) reject("a count certificate cannot rest on a user factor");
  if (!c_.m.constraints.empty()) reject("a count certificate's model has no constraint");
  const int64_t total = c_.rd.expect({"count"}, 2).integer();
  first_ = long(c_.rd.integer());
  if (first_ != long(c_.R.size())) reject("count: the first cover is the tree's output boxes");
  if (total < first_ || total > (int64_t(1) << 30)) reject("count: bad number of cells");
  cells_.resize(size_t(total));
  for (long i = 0; i < first_; ++i) {
    Cell& cell = cells_[i];
    cell.origin.assign(c_.R.box(i), c_.R.box(i) + 2 * nv_);
    cell.box = cell.origin;
    cell.solution = c_.R.solution[i];
    cell.state = State::Live;
  }
  for (;;) {
    c_.rd.next();
    const std::string k(c_.rd.kind());
    if (k == "claim") break;
    if (k == "half") half();
    else if (k == "fit") fit(false);
    else if (k == "void") fit(true);
    else if (k == "none") none();
    else if (k == "split") split();
    else if (k == "piece") piece();
    else if (k == "refuted" || k == "joined") {
      if (last_id_ < long(cells_.size())) every_cell_made();
      last_id_ = long(cells_.size());  // no cell record after the adjacencies
      if (k == "refuted") refuted();
      else joined();
    } else malformed(rec(), "unknown count record '" + k + "'");
  }
  every_cell_made();
  finish();
  const int64_t claim = c_.rd.require({"claim", "count-lower"}, 1).integer();
  const long claim_rec = rec();
  if (claim < 0) malformed(rec(), "negative lower bound");
  c_.rd.expect({"claim", "count-upper"}, 1);
  const long upper_rec = rec();
  const std::string upper(c_.rd.word());
  const int64_t upper_claim = upper == "none" ? -1 : parse_int(upper, rec());
  if (upper != "none" && upper_claim < 0) malformed(rec(), "negative upper bound");
  const int64_t records = c_.rd.expect({"end"}, 1).integer();
  if (records != rec() - 1) malformed(rec(), "end: wrong record count");
  c_.rd.expect_eof();
  long cover = 0;
  for (const Cell& cell : cells_) cover += cell.state == State::Live;
  c_.out.count_cells = cover;
  c_.out.recomputed = c_.out.checked = lower_bound();
  c_.out.claimed = claim;
  if (claim > c_.out.recomputed)
    rejected(claim_rec, "claimed lower bound " + std::to_string(claim) + " exceeds the recomputed " +
                            std::to_string(c_.out.recomputed));
  if (upper_claim >= 0) {
    // Printed only when every piece's connectedness and every join is verified here.
    const long u = upper_bound();
    if (u < 0) rejected(upper_rec, "claimed upper bound " + upper + " is not proved: " + upper_open_);
    if (upper_claim < u)
      rejected(upper_rec, "claimed upper bound " + upper + " is below the recomputed " + std::to_string(u));
    c_.out.count_upper = u;
  }
  c_.out.outcome = Outcome::Verified;
}

}  // namespace cc
