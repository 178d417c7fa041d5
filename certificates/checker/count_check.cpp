// count_check.cpp — trusted core: the records of a count certificate (FORMAT.md, "Count
// certificates") after its search tree: how each box of the final cover came from the
// tree's output boxes (halves of bisections with their contractions, charts, boxes with no
// solution), the pieces and adjacencies, and the claims: the lower bound recomputed from
// these alone, the upper bound only when count_connected.cpp proved every piece connected.
#include "count_check.h"

namespace cc {

void Checker::count_body() { CountCheck(*this).run(); }

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

// fit ID W W~ BOX: BOX's u holds the origin's u (the same, or a little larger: then the
// cell's box overlaps its neighbours, and joins have room), in the root cell; the chart's
// iterate W̃ holds the origin's w; Hansen–Sengupta on BOX_u × W̃ gives H ⊆ int W̃, so every
// solution of BOX_u × W̃, the origin's among them, is (u, w(u)) with w(u) ∈ H, and in
// origin_w ∩ H (∩ the domain's enclosure on a non-periodic w) for the origin's, which BOX
// holds; BOX lies in W̃ (so V ∩ BOX is the graph over BOX_u cut by BOX's w).
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
  for (int v = 0; v < nv_ && !void_only; ++v) {
    if (std::find(w.begin(), w.end(), v) != w.end()) continue;
    if (!within(B[2 * v], B[2 * v + 1], cell.origin[2 * v], cell.origin[2 * v + 1]))
      reject("chart: the box's " + c_.m.vars[v].name + " does not hold the origin's");
    if (!within(c_.root[2 * v], c_.root[2 * v + 1], B[2 * v], B[2 * v + 1]))
      reject("chart: the box's " + c_.m.vars[v].name + " leaves the root cell");
    b[v].set(B[2 * v], B[2 * v + 1]);
  }
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
    if (it == w.end()) continue;  // u: checked above
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
    } else if (proof == "constraint") {
      Dnf terms;
      if (reduce(ivals(cell.box), terms) != Reduced::False)
        reject("empty by a constraint: no constraint is False on the box" + c_.show(cell.box));
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

void CountCheck::every_cell_made() {
  for (const Cell& cell : cells_)
    if (cell.state == State::Unmade || cell.state == State::Pending)
      reject("count: a cell announced is never made, or a half never given its box");
}

void CountCheck::run() {
  if (c_.p > kMaxCountFactors) reject("a count certificate has at most 6 factors");
  for (const Factor& f : c_.factors)
    if (f.kind == Factor::User) reject("a count certificate cannot rest on a user factor");
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
