#include "counting/exact_count.h"

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <unordered_map>

#include "aspects/neighborhood_graph.h"
#include "checker_gap.h"
#include "contractor.h"
#include "counting/chart.h"
#include "counting/class_point.h"
#include "counting/constraint_reduction.h"
#include "counting/empty_piece.h"
#include "counting/factor_gradients.h"
#include "counting/star_test.h"
#include "generalized_aspects.h"
#include "link.h"

namespace aspects {

const char* open_reason_name(OpenReason r) {
  switch (r) {
    case OpenReason::NoChart: return "no chart proved (pose, command or mixed)";
    case OpenReason::NoPoint: return "no certified point of the class found";
    case OpenReason::NotStar: return "star-shaped test failed";
    case OpenReason::Adjacency: return "adjacency neither joined nor refuted";
    case OpenReason::NotReached: return "not decided before the stop";
    case OpenReason::ConstraintBoundary:
      return "constraint boundary (an 'or' left undecided on the box)";
  }
  return "?";
}

const char* count_stop_name(CountStop s) {
  switch (s) {
    case CountStop::Exact: return "exact";
    case CountStop::MinWidth: return "least width reached";
    case CountStop::Rounds: return "round budget spent";
    case CountStop::Stopped: return "stopped (time limit or signal)";
  }
  return "?";
}

namespace {

constexpr size_t kMaxOpenPlaces = 8;
constexpr double kFaceMargin = 1e-6;  // relative to the width of what it pushes out

// [lo, hi] pushed out by kFaceMargin of its width at each end, not past floor and ceil (an
// end already past them stays): a contracted end passes through the point where the graph
// leaves the box, so a join's witness there, or a face of the star test, would otherwise
// have to be decided to the last bit.
Interval pushed_out(double lo, double hi, double floor, double ceil) {
  const double margin = kFaceMargin * (hi - lo);
  Interval x;
  x.set_hull(std::min(lo, std::max(lo - margin, floor)), std::max(hi, std::min(hi + margin, ceil)));
  return x;
}

struct PieceRec {
  PieceRec(uint32_t c, PieceState s, OpenReason w,
           CountCellRecord::EmptyBy e = CountCellRecord::NotEmpty, ClassPoint p = {},
           CountCellRecord::ConnectedBy by = CountCellRecord::NotConnected)
      : cls(c), state(s), why(w), empty_by(e), point(std::move(p)), connected_by(by) {}
  uint32_t cls;
  PieceState state;
  OpenReason why;
  // For the certificate: why it is empty, or a point of W_s in the box (u empty: none).
  CountCellRecord::EmptyBy empty_by;
  ClassPoint point;
  CountCellRecord::ConnectedBy connected_by;
};

struct Cell {
  Box box;                     // closed, double ends; holds every solution it covers
  bool solution = false;       // a solve's solution box: P1 made V ∩ B a graph over [x]
  bool decided = false;        // pieces computed
  bool alive = true;
  // A chart held but a star test failed: bisect its u (a shorter graph is straighter; a
  // bisection in w only cuts the graph into thinner, as curved, strips).
  std::vector<int> split_in;  // empty, or the chart's u, to bisect
  std::vector<PieceRec> pieces;
  int32_t node = -1;           // its leaf in the refinement tree
  // The variable whose bisection made it (-1: a box of the first cover). It does not grow
  // back across that cut: both halves of a w-part would grow to the same range.
  int8_t cut_var = -1;
  // For the certificate: the box as created, the chart that changed it, the bisection.
  Box origin;
  CountCellRecord::Fit fit = CountCellRecord::NoFit;
  Chart chart;
  int split_var = -1;
  double split_at = 0;
  int32_t child[2] = {-1, -1};
};

struct ClassEdge {
  ClassEdge(uint32_t c) : cls(c) {}  // NOLINT: built from its class in a brace list
  uint32_t cls;
  AdjacencyState state = AdjacencyState::Undecided;
  bool tried = false;
  // For the certificate, when joined: the shift, and the point or the bridge's chart.
  std::vector<int> shift;
  ClassPoint point;
  Chart bridge;
};

struct Adj {
  int32_t a, b;
  std::vector<std::vector<int>> shifts;  // k per variable: b + 2πk meets a
  std::vector<ClassEdge> classes;
};

class Counter {
 public:
  Counter(Model& m, const CountConfig& config, const FactorGradients& fg,
          const FactorGradients* atoms)
      : m_(m), config_(config), fg_(fg), atoms_(atoms), ev_(m), contractor_(ev_),
        check_(m, ev_), reducer_(m), nv_(int(m.vars.size())) {
    if (!check_.empty()) feasible_.check = &check_;
    two_pi_ = Interval(0.0);
    mpfi_const_pi(two_pi_.get());
    mpfi_mul_ui(two_pi_.get(), two_pi_.get(), 2);
    for (const auto& v : m.vars) {
      periodic_.push_back(v.periodic);
      domain_width_.push_back(v.periodic ? 2 * M_PI : std::max(v.domain.width_up(), 1e-300));
    }
  }

  // The solve's output boxes and its tree: a leaf per box, bisected further where needed. The
  // tree is the bounding-volume hierarchy of the neighbourhood graph (recomputed each round
  // on the boxes as they are: a box with a chart becomes U × the range of its graph).
  void add_first_cover(const AspectsResult& solved) {
    separation_bound_ = solved.separation.lower_bound;
    const OutputBoxes& R = solved.boxes;
    first_cover_ = R.size();
    cells_.reserve(R.size());
    for (int i = 0; i < R.size(); ++i) {
      Cell c;
      c.box.resize(nv_);
      for (int v = 0; v < nv_; ++v) c.box[v].set_hull(R.lo(i, v), R.hi(i, v));
      c.solution = R.certified(i);
      c.origin = c.box;
      cells_.push_back(std::move(c));
    }
    tree_ = solved.tree;
    for (size_t t = 0; t < tree_.size(); ++t)
      if (!tree_[t].internal() && tree_[t].leaf() >= 0) cells_[tree_[t].leaf()].node = int32_t(t);
  }

  // M on the boxes of this round; the decisions of pairs already met are kept.
  void rebuild_adjacencies() {
    BoxStore R(nv_);
    R.reserve(cells_.size());
    for (const Cell& c : cells_) R.push(c.box);
    std::unordered_map<uint64_t, int32_t> index;
    std::vector<Adj> fresh;
    for (const NeighborPair& p : neighbor_pairs(tree_, R, periodic_)) {
      // Every id is queried, a bisected box's too: its pairs are not the cover's.
      if (!cells_[p.a].alive || !cells_[p.b].alive) continue;
      const uint64_t key = (uint64_t(uint32_t(p.a)) << 32) | uint32_t(p.b);
      auto old = adj_index_.find(key);
      if (old != adj_index_.end()) {
        fresh.push_back(std::move(adj_[old->second]));
      } else {
        Adj e;
        e.a = p.a, e.b = p.b;
        e.shifts = touching_shifts(cells_[p.a].box, cells_[p.b].box);
        if (e.shifts.empty()) {  // M rounds the shifted ends itself: take its shift too
          std::vector<int> k(nv_);
          for (int v = 0; v < nv_; ++v) k[v] = p.shift(v);
          e.shifts.push_back(k);
        }
        fresh.push_back(std::move(e));
      }
      index[key] = int32_t(fresh.size()) - 1;
    }
    adj_ = std::move(fresh);
    adj_index_ = std::move(index);
  }

  CountResult run() {
    CountResult out;
    for (int round = 0;; ++round) {
      out.rounds = round + 1;
      bool stop = false;
      for (size_t c = 0; c < cells_.size() && !stop; ++c) {
        if (cells_[c].alive && !cells_[c].decided) decide_cell(int32_t(c));
        if (c % 64 == 0) stop = stopped();
      }
      if (stop || stopped()) {
        out.stop = CountStop::Stopped;
        if (round == 0) {
          // Stopped before a decision: the lower bound is the first cover's separation (the
          // same graph with every adjacency undecided, C1), no upper bound. The graph of a
          // first cover can be far larger than what the stop left time for.
          out.bounds = CountBounds{};
          out.bounds.lower = separation_bound_;
          for (const Cell& c : cells_) out.bounds.open_pieces += c.alive && !c.solution;
          // Said as what it is: none of them was decided.
          out.open_by_reason[int(OpenReason::NotReached)] = out.bounds.open_pieces;
          break;
        }
        // The boxes not decided yet have undecided pieces: the bounds still hold.
        for (Cell& c : cells_)
          if (c.alive && !c.decided) leave_undecided(c);
        bounds_and_open(out, false);
        break;
      }
      rebuild_adjacencies();
      std::vector<int32_t> refine;
      CountBounds b = decide_adjacencies_and_bound(refine, out);
      if (config_.progress) config_.progress(round, b, alive_cells(), out.open_by_reason, config_.progress_data);
      if (b.exact()) {
        out.stop = CountStop::Exact;
        break;
      }
      if (stopped()) {
        out.stop = CountStop::Stopped;
        break;
      }
      if (round + 1 >= config_.max_rounds) {
        out.stop = CountStop::Rounds;
        break;
      }
      size_t bisected = 0;
      for (int32_t c : refine)
        if (cells_[c].alive && bisect(c)) ++bisected, ++out.bisections;
      if (bisected == 0) {
        out.stop = CountStop::MinWidth;
        break;
      }
    }
    out.cells = alive_cells();
    out.star_boxes = star_boxes_;
    return out;
  }

 private:
  // Any stop ends the refinement, a first Ctrl-C too (it stops only a solve's search): the
  // bounds reached are printed.
  bool stopped() const {
    return config_.stop && (config_.stop->search_stopped() || config_.stop->poll());
  }

  long alive_cells() const {
    long n = 0;
    for (const Cell& c : cells_) n += c.alive;
    return n;
  }

  // ----- geometry: b + 2πk against a, outward (may meet) or inward (certainly in both).
  void shifted(double lo, double hi, int k, double& slo, double& shi) {
    if (k == 0) {
      slo = lo, shi = hi;
      return;
    }
    Interval t;
    mpfi_mul_si(t.get(), two_pi_.get(), k);
    Interval e;
    mpfi_add_d(e.get(), t.get(), lo);
    slo = e.lo_down();
    mpfi_add_d(e.get(), t.get(), hi);
    shi = e.hi_up();
  }

  bool outer_meet(const Box& a, const Box& b, const std::vector<int>& k, Box& out) {
    out.resize(nv_);
    for (int v = 0; v < nv_; ++v) {
      double lo, hi;
      shifted(b[v].lo_down(), b[v].hi_up(), k[v], lo, hi);
      lo = std::max(lo, a[v].lo_down());
      hi = std::min(hi, a[v].hi_up());
      if (!(lo <= hi)) return false;
      out[v].set_hull(lo, hi);
    }
    return true;
  }

  bool inner_meet(const Box& a, const Box& b, const std::vector<int>& k, Box& out) {
    out.resize(nv_);
    for (int v = 0; v < nv_; ++v) {
      double lo, hi;
      if (!inner_intersection(a[v].lo_down(), a[v].hi_up(), b[v].lo_down(), b[v].hi_up(), k[v],
                              lo, hi))
        return false;
      out[v].set_hull(lo, hi);
    }
    return true;
  }

  // Every shift k ∈ {−1, 0, 1} on the periodic variables under which the closed boxes meet.
  std::vector<std::vector<int>> touching_shifts(const Box& a, const Box& b) {
    std::vector<std::vector<int>> found;
    std::vector<int> k(nv_, 0);
    std::vector<int> per;
    for (int v = 0; v < nv_; ++v)
      if (periodic_[v]) per.push_back(v);
    for (int v : per) k[v] = -1;
    Box scratch;
    for (;;) {
      if (outer_meet(a, b, k, scratch)) found.push_back(k);
      size_t i = 0;
      for (; i < per.size(); ++i) {
        if (++k[per[i]] <= 1) break;
        k[per[i]] = -1;
      }
      if (i == per.size()) break;
    }
    return found;
  }

  // A box the refinement did not reach: a piece of every class its signs allow, undecided.
  void leave_undecided(Cell& c) {
    c.decided = true;
    c.pieces.clear();
    std::vector<Interval> values;
    const bool defined = fg_.values(ev_, c.box, values);
    for (uint32_t s = 0; s < (uint32_t(1) << fg_.factors()); ++s)
      if (!defined || !class_empty(values, s))
        c.pieces.push_back({s, PieceState::Undecided, OpenReason::NotReached});
  }

  // ----- pieces
  bool class_empty(const std::vector<Interval>& values, uint32_t cls) const {
    for (size_t i = 0; i < values.size(); ++i) {
      const bool positive = (cls >> i) & 1;
      // No point where s_i·g_i > 0: the closed enclosure is on the other side of 0.
      if (positive ? values[i].hi_up() <= 0 : values[i].lo_down() >= 0) return true;
    }
    return false;
  }

  void decide_cell(int32_t id) {
    Cell& c = cells_[id];
    c.decided = true;
    c.pieces.clear();
    const int p = fg_.factors();
    std::vector<Interval> values;
    const bool defined = fg_.values(ev_, c.box, values);
    std::vector<uint32_t> classes;
    for (uint32_t s = 0; s < (uint32_t(1) << p); ++s)
      if (!defined || !class_empty(values, s)) classes.push_back(s);
    if (constraint_false(c, classes)) return;

    Chart chart;
    ChartVerdict cv = ChartVerdict::NotProved;
    if (c.solution) {
      // P1 of the solve: for every x of [x] one q in [q~] ⊇ [q]; the solve's box holds every
      // solution of its cell, so V ∩ B is the graph of q over [x].
      chart.w = m_.command;
      chart.u = m_.pose;
      chart.w_range.clear();
      for (int w : chart.w) chart.w_range.push_back(c.box[w]);
      cv = ChartVerdict::Proved;
    } else {
      for (const std::vector<int>& w : chart_candidates(ev_, c.box, domain_width_)) {
        cv = prove_chart(ev_, c.box, w, ws_, chart);
        if (cv != ChartVerdict::NotProved) break;
      }
    }
    if (cv == ChartVerdict::NoSolution) {
      c.fit = CountCellRecord::NoSolution;
      for (uint32_t s : classes)
        c.pieces.push_back({s, PieceState::Empty, OpenReason::NoPoint, CountCellRecord::NoPoint});
      return;
    }
    if (cv == ChartVerdict::Proved) {
      if (!c.solution) grow_u(c, chart);
      decide_charted(c, chart, classes);
      return;
    }
    // No chart: the box is bisected whatever else is proved of it (a point would only show
    // its piece nonempty, which the solution boxes already do for the lower bound), across
    // the chart likeliest to hold on its halves.
    const int cut = chart_split_variable(ev_, c.box, domain_width_);
    if (cut >= 0) c.split_in = {cut};
    for (uint32_t s : classes) c.pieces.push_back({s, PieceState::Undecided, OpenReason::NoChart});
  }

  // No feasible point in the box (a constraint False on it): every piece is empty.
  bool constraint_false(Cell& c, const std::vector<uint32_t>& classes) {
    if (check_.empty() || check_.evaluate(c.box) != Truth::False) return false;
    c.pieces.clear();
    for (uint32_t s : classes)
      c.pieces.push_back({s, PieceState::Empty, OpenReason::NoPoint, CountCellRecord::Constraint});
    return true;
  }

  // U pushed out a little inside the domain, when the chart holds there too: the neighbour
  // across a contracted face begins where the graph leaves this box; with the overlap a
  // join's witness has room. (The cover only needs boxes holding their origin's solutions:
  // a larger box holds them too.)
  void grow_u(Cell& c, Chart& chart) {
    Box grown = c.box;
    bool changed = false;
    for (int v : chart.u) {
      // Within the domain; a periodic one's too: not across the seam.
      grown[v] = pushed_out(c.box[v].lo_down(), c.box[v].hi_up(), m_.vars[v].domain.lo_down(),
                            m_.vars[v].domain.hi_up());
      changed = changed || grown[v].lo_down() < c.box[v].lo_down() ||
                grown[v].hi_up() > c.box[v].hi_up();
    }
    if (!changed) return;
    Chart wider;
    if (prove_chart(ev_, grown, chart.w, ws_, wider) != ChartVerdict::Proved) return;
    c.box = std::move(grown);
    chart = std::move(wider);
  }

  // The pieces of a box on which `chart` is proved (FORMAT.md "Counting", C2–C4).
  void decide_charted(Cell& c, const Chart& chart, const std::vector<uint32_t>& classes) {
    const int n = m_.n(), p = fg_.factors();
    // z: U × the range of w (every w(u), u ∈ U, lies in it).
    Box z = c.box;
    for (int j = 0; j < n; ++j) z[chart.w[j]] = chart.w_range[j];
    std::vector<StarConstraint> faces;
    bool inside = true;  // w(U) ⊆ W: the graph is over the whole of U
    if (!c.solution) {
      c.chart = chart;
      c.fit = CountCellRecord::Charted;
    }
    if (!fit_box_to_chart(c, chart, z, faces, inside)) {
      c.fit = CountCellRecord::Void;
      for (uint32_t s : classes)
        c.pieces.push_back({s, PieceState::Empty, OpenReason::NoPoint, CountCellRecord::NoPoint});
      return;
    }
    // The constraints on the box as fitted (C7): False, every piece is empty; else the atoms
    // left are constraints of the pieces (an `or` left: one set of them per term, the piece
    // their union; too many terms: undecided).
    if (constraint_false(c, classes)) return;
    const ReducedConstraints reduced = reducer_.reduce(ev_, c.box);
    const bool is_union = reduced.outcome == Reduced::Disjunction;
    if ((is_union && reduced.terms.empty()) || (c.solution && reduced.outcome != Reduced::True)) {
      for (uint32_t s : classes)
        c.pieces.push_back({s, PieceState::Undecided, OpenReason::ConstraintBoundary});
      c.split_in = chart.u;
      return;
    }
    // The piece is the union over the terms of the graph over {u : the factors, the faces
    // and the term's atoms hold}: star-shaped about v when each is (one centre for all).
    const std::vector<std::vector<int>> terms =
        is_union ? reduced.terms : std::vector<std::vector<int>>{reduced.atoms};
    std::vector<int> atoms;  // every atom of every term: the centre satisfies them all
    for (const std::vector<int>& t : terms)
      for (int k : t)
        if (std::find(atoms.begin(), atoms.end(), k) == atoms.end()) atoms.push_back(k);
    const OpenReason not_star = is_union ? OpenReason::ConstraintBoundary : OpenReason::NotStar;
    std::vector<Interval> zv;
    const bool zdefined = fg_.values(ev_, c.box, zv);  // the piece lies in the box
    const bool certain = zdefined && all_signs_certain(zv);
    if (certain && inside && atoms.empty()) {
      // Every factor has one sign on the graph over U (connected, nonempty): one class.
      uint32_t cls = 0;
      for (int i = 0; i < p; ++i) cls |= uint32_t(zv[i].certainly_pos()) << i;
      for (uint32_t s : classes)
        c.pieces.push_back({s, s == cls ? PieceState::Connected : PieceState::Empty,
                            OpenReason::NoPoint,
                            s == cls ? CountCellRecord::NotEmpty : CountCellRecord::Signs,
                            ClassPoint{}, CountCellRecord::Graph});
      return;
    }
    if (c.solution) {
      decide_solution_graph(c, chart, classes);
      return;
    }
    std::unique_ptr<ClassPointSearch> points;  // made when a class needs it
    PointConstraints with_atoms = feasible_;
    with_atoms.atoms = atoms_;
    with_atoms.which = atoms;
    // An atom is a constraint of the star test only where it is continuous: its expression
    // defined on U × the range of w.
    std::vector<Interval> av;
    const bool atoms_defined = atoms.empty() || (atoms_ && atoms_->values(ev_, z, av));
    for (uint32_t s : classes) {
      if (zdefined && class_empty(zv, s)) {
        c.pieces.push_back({s, PieceState::Empty, OpenReason::NoPoint, CountCellRecord::Signs});
        continue;
      }
      ClassPoint centre;
      if (!points)
        points = std::make_unique<ClassPointSearch>(ev_, fg_, c.box, chart.w, 3, &with_atoms);
      if (points->find(s, ws_, centre) != PointVerdict::Found) {
        const bool empty =
            prove_piece_empty(ev_, fg_, chart, c.box, s, ws_, 4000,
                              check_.empty() ? nullptr : &check_) == EmptyVerdict::Empty;
        c.pieces.push_back({s, empty ? PieceState::Empty : PieceState::Undecided,
                            is_union ? OpenReason::ConstraintBoundary : OpenReason::NoPoint,
                            empty ? CountCellRecord::Paving : CountCellRecord::NotEmpty});
        // No centre in every term: bisected in u, as a box left with its `or` undecided.
        if (!empty && is_union) c.split_in = chart.u;
        continue;
      }
      std::vector<StarConstraint> base = faces;
      for (int i = 0; i < p; ++i)
        if (!zdefined || !(zv[i].certainly_pos() || zv[i].certainly_neg()))
          base.push_back({StarConstraint::Factor, i, (s >> i) & 1 ? 1 : -1, 0});
      const bool star = atoms_defined && star_in_every_term(chart, z, base, terms, centre);
      c.pieces.push_back({s, star ? PieceState::Connected : PieceState::Nonempty,
                          not_star, CountCellRecord::NotEmpty, centre,
                          star ? CountCellRecord::Star : CountCellRecord::NotConnected});
      if (!star) c.split_in = chart.u;
    }
  }

  // A solution box: the graph is connected and every factor nonzero on it (P2), so it lies in
  // one class, the class of any of its points.
  void decide_solution_graph(Cell& c, const Chart& chart, const std::vector<uint32_t>& classes) {
    ClassPointSearch points(ev_, fg_, c.box, chart.w, 1, &feasible_);
    for (uint32_t s : classes) {
      ClassPoint pt;
      if (points.find(s, ws_, pt) != PointVerdict::Found) continue;
      for (uint32_t t : classes)
        c.pieces.push_back({t, t == s ? PieceState::Connected : PieceState::Empty,
                            OpenReason::NoPoint,
                            t == s ? CountCellRecord::NotEmpty : CountCellRecord::OtherClass,
                            t == s ? pt : ClassPoint{}, CountCellRecord::Graph});
      return;
    }
    for (uint32_t s : classes) c.pieces.push_back({s, PieceState::Undecided, OpenReason::NoPoint});
  }

  // The piece is the union over the terms of the set where `base` and the term's atoms hold:
  // star-shaped about `centre` when each term's set is (C7).
  bool star_in_every_term(const Chart& chart, const Box& z, const std::vector<StarConstraint>& base,
                          const std::vector<std::vector<int>>& terms, const ClassPoint& centre) {
    for (const std::vector<int>& term : terms) {
      std::vector<StarConstraint> tests = base;
      for (int k : term) {
        const auto kind = reducer_.strict(k) ? StarConstraint::AtomStrict
                                             : StarConstraint::AtomClosed;
        tests.push_back({kind, k, 1, 0});
      }
      if (star_test(ev_, fg_, chart, z, tests, centre.u, centre.w, StarLimits{}, ws_,
                    star_boxes_, atoms_) != StarVerdict::StarShaped)
        return false;
    }
    return true;
  }

  // The box as the chart makes it: its W met with the range, with the faces of W the graph
  // crosses, or grown to the range. False when the box holds no solution.
  bool fit_box_to_chart(Cell& c, const Chart& chart, const Box& z,
                        std::vector<StarConstraint>& faces, bool& inside) {
    const int n = m_.n();
    // The box keeps its W, met with the range (every solution of B is on the graph): the
    // piece is the graph over {u ∈ U : w(u) ∈ W}, whose faces are constraints of the star
    // test. (Growing the box to U × the range instead made it overlap its neighbours, the
    // more so as the range is overestimated: on RRRRR ten times the adjacencies.)
    faces.clear();
    inside = true;
    // A box contracted around its solutions touches them at its faces, tangentially where
    // w has an extreme inside U: a face constraint there cannot be cleared. When the range
    // is little wider than the box (no cut, only overestimation), the box grows to it
    // within the domain instead, and only the domain's faces remain.
    // So does a box on whose U × range every factor has one sign: its piece is then the
    // whole graph, connected with no test (a star test with the cut's faces costs tens of
    // sub-boxes).
    std::vector<Interval> rv;
    const bool one_class = fg_.values(ev_, z, rv) && all_signs_certain(rv);
    if (!c.solution && (one_class || small_growth(c.box, chart))) {
      for (int j = 0; j < n; ++j) {
        const int v = chart.w[j];
        if (v == c.cut_var) continue;
        double lo = chart.w_range[j].lo_down(), hi = chart.w_range[j].hi_up();
        if (!periodic_[v]) {
          lo = std::max(lo, m_.vars[v].domain.lo_down());
          hi = std::min(hi, m_.vars[v].domain.hi_up());
        }
        c.box[v].set_hull(lo, hi);
      }
    }
    for (int j = 0; j < n; ++j) {
      const int v = chart.w[j];
      const double lo = std::max(c.box[v].lo_down(), chart.w_range[j].lo_down());
      const double hi = std::min(c.box[v].hi_up(), chart.w_range[j].hi_up());
      if (!(lo <= hi)) return false;  // no solution in the box
      if (!c.solution) {
        // An end the box sets (not the range) is pushed out, within the range (and the
        // domain on a non-periodic w).
        double floor = lo > chart.w_range[j].lo_down() ? chart.w_range[j].lo_down() : lo;
        double ceil = hi < chart.w_range[j].hi_up() ? chart.w_range[j].hi_up() : hi;
        if (!periodic_[v]) {
          floor = std::max(floor, m_.vars[v].domain.lo_down());
          ceil = std::min(ceil, m_.vars[v].domain.hi_up());
        }
        c.box[v] = pushed_out(lo, hi, floor, ceil);
      }
      if (chart.w_range[j].lo_down() < c.box[v].lo_down()) {
        faces.push_back({StarConstraint::WLower, j, 1, c.box[v].lo_down()});
        inside = false;
      }
      if (chart.w_range[j].hi_up() > c.box[v].hi_up()) {
        faces.push_back({StarConstraint::WUpper, j, 1, c.box[v].hi_up()});
        inside = false;
      }
    }
    return true;
  }

  static bool all_signs_certain(const std::vector<Interval>& values) {
    for (const Interval& x : values)
      if (!(x.certainly_pos() || x.certainly_neg())) return false;
    return true;
  }

  // The chart's range sticks out of the box by at most the box's width on each side.
  bool small_growth(const Box& box, const Chart& chart) const {
    for (size_t j = 0; j < chart.w.size(); ++j) {
      const Interval& W = box[chart.w[j]];
      const double margin = W.width_up();
      if (chart.w_range[j].lo_down() < W.lo_down() - margin ||
          chart.w_range[j].hi_up() > W.hi_up() + margin)
        return false;
    }
    return true;
  }

  const PieceRec* piece(int32_t cell, uint32_t cls) const {
    for (const PieceRec& r : cells_[cell].pieces)
      if (r.cls == cls) return &r;
    return nullptr;  // the class is certainly absent from the box
  }

  // ----- adjacencies
  AdjacencyState try_join(const Adj& e, uint32_t cls, ClassEdge& proof) {
    Box face;
    for (const std::vector<int>& k : e.shifts) {
      if (!inner_meet(cells_[e.a].box, cells_[e.b].box, k, face)) continue;
      // A face flat in a variable is reached in a chart where that variable is u.
      std::vector<std::vector<int>> charts = chart_candidates(ev_, face, domain_width_);
      std::stable_partition(charts.begin(), charts.end(), [&](const std::vector<int>& w) {
        for (int v : w)
          if (face[v].lo_down() == face[v].hi_up()) return false;
        return true;
      });
      // A witness must be feasible: a point where every constraint is True.
      PointConstraints pc = feasible_;
      if (!check_.empty()) {
        const ReducedConstraints r = reducer_.reduce(ev_, face);
        if (r.outcome == Reduced::False) continue;
        pc.atoms = atoms_;
        pc.which = r.atoms;
      }
      ClassPoint pt;
      for (const std::vector<int>& w : charts)
        if (find_class_point(ev_, fg_, face, w, cls, ws_, pt, 3, &pc) == PointVerdict::Found) {
          proof.shift = k;
          proof.point = pt;
          return AdjacencyState::Joined;
        }
    }
    // Boxes that meet only at a corner of the graph leave no room for a witness: a bridge
    // instead. With C the hull of both boxes, a chart on C makes V ∩ C a graph over U_C;
    // when the graph stays in the domain and every factor has the sign of the class on
    // U_C × (its range), that graph is a connected subset of W_s holding both pieces (each
    // box lies in C), so they are in one aspect.
    for (const std::vector<int>& k : e.shifts) {
      Box hull = cells_[e.a].box;
      for (int v = 0; v < nv_; ++v) {
        double lo, hi;
        shifted(cells_[e.b].box[v].lo_down(), cells_[e.b].box[v].hi_up(), k[v], lo, hi);
        hull[v].set_hull(std::min(lo, hull[v].lo_down()), std::max(hi, hull[v].hi_up()));
      }
      if (bridged(hull, cls, proof.bridge)) {
        proof.shift = k;
        return AdjacencyState::Joined;
      }
    }
    return AdjacencyState::Undecided;
  }

  bool bridged(const Box& hull, uint32_t cls, Chart& chart) {
    std::vector<Interval> values;
    for (const std::vector<int>& w : chart_candidates(ev_, hull, domain_width_)) {
      if (prove_chart(ev_, hull, w, ws_, chart) != ChartVerdict::Proved) continue;
      Box z = hull;
      bool in_domain = true;
      for (size_t j = 0; j < chart.w.size(); ++j) {
        const int v = chart.w[j];
        z[v] = chart.w_range[j];
        if (!periodic_[v] && !m_.vars[v].domain.contains(z[v])) in_domain = false;
      }
      if (!in_domain || !fg_.values(ev_, z, values)) continue;
      // The whole graph feasible: every constraint True on U_C × its range.
      if (!check_.empty() && check_.evaluate(z) != Truth::True) continue;
      bool all = true;
      for (size_t i = 0; i < values.size(); ++i)
        all = all && ((cls >> i) & 1 ? values[i].certainly_pos() : values[i].certainly_neg());
      if (all) return true;
    }
    return false;
  }

  AdjacencyState try_refute(const Adj& e, uint32_t cls) {
    Box face;
    std::vector<Interval> values;
    for (const std::vector<int>& k : e.shifts) {
      if (!outer_meet(cells_[e.a].box, cells_[e.b].box, k, face)) continue;
      if (contractor_.contract(face)) continue;  // no solution in the closed intersection
      // No feasible point in it.
      if (!check_.empty() && check_.evaluate(face) == Truth::False) continue;
      if (fg_.values(ev_, face, values) && class_empty(values, cls)) continue;
      return AdjacencyState::Undecided;
    }
    return AdjacencyState::Refuted;
  }

  // An adjacency's class in the round's graph: adj_[adj].classes[klass] is its edge `edge`.
  struct EdgeRef {
    int32_t adj, klass, edge;
  };

  CountBounds decide_adjacencies_and_bound(std::vector<int32_t>& refine, CountResult& out) {
    CountGraph g;
    std::vector<EdgeRef> edges;
    build_round_graph(g, edges);
    decide_between_components(g, edges);
    const CountBounds b = g.bounds();
    out.bounds = b;
    out.regions = regions(g);
    out.pieces = g.pieces();
    out.adjacencies = g.adjacencies();
    mark_open(g, edges, refine, out);
    return b;
  }

  // The lower bound's components with where they lie; build_round_graph numbers the pieces
  // cell by cell, in the cells' order.
  std::vector<CountRegion> regions(const CountGraph& g) const {
    const std::vector<int32_t> gc = g.unrefuted_components();
    std::vector<CountRegion> rs;
    std::vector<uint8_t> nonempty;
    int32_t node = 0;
    for (const Cell& c : cells_) {
      if (!c.alive) continue;
      for (const PieceRec& r : c.pieces) {
        const int32_t k = gc[node++];
        if (k < 0 || r.state == PieceState::Empty) continue;
        if (size_t(k) >= rs.size()) rs.resize(k + 1), nonempty.resize(k + 1, 0);
        CountRegion& x = rs[k];
        if (x.boxes == 0) {
          x.lo.assign(nv_, std::numeric_limits<double>::infinity());
          x.hi.assign(nv_, -std::numeric_limits<double>::infinity());
        }
        double volume = 1;
        for (int v = 0; v < nv_; ++v) {
          const double lo = c.box[v].lo_down(), hi = c.box[v].hi_up();
          x.lo[v] = std::min(x.lo[v], lo);
          x.hi[v] = std::max(x.hi[v], hi);
          // A pose fixed by its domain (3-RRR*'s x3 in [0, 0]) takes no part in the volume.
          if (m_.vars[v].kind == VarKind::Pose && m_.vars[v].domain.width_up() > 0)
            volume *= hi - lo;
        }
        x.cls = r.cls;
        ++x.boxes;
        x.connected += r.state == PieceState::Connected;
        x.pose_volume += volume;
        nonempty[k] |= r.state == PieceState::Connected || r.state == PieceState::Nonempty;
      }
    }
    std::vector<CountRegion> out;
    for (size_t k = 0; k < rs.size(); ++k)
      if (nonempty[k]) out.push_back(std::move(rs[k]));
    std::stable_sort(out.begin(), out.end(), [](const CountRegion& a, const CountRegion& b) {
      return a.pose_volume > b.pose_volume;
    });
    return out;
  }

  // The graph of this round: one node per piece of a live cell, an edge per class of an
  // adjacency whose two pieces are not empty.
  void build_round_graph(CountGraph& g, std::vector<EdgeRef>& edges) {
    std::vector<std::vector<int32_t>> node(cells_.size());
    for (size_t c = 0; c < cells_.size(); ++c) {
      if (!cells_[c].alive) continue;
      for (const PieceRec& r : cells_[c].pieces) node[c].push_back(g.add_piece(r.cls, r.state));
    }
    auto node_of = [&](int32_t cell, uint32_t cls) -> int32_t {
      if (!cells_[cell].alive || node[cell].size() != cells_[cell].pieces.size())
        throw std::logic_error("count: adjacency of a cell that is not in the cover (" +
                               std::to_string(cell) + ")");
      const auto& ps = cells_[cell].pieces;
      for (size_t i = 0; i < ps.size(); ++i)
        if (ps[i].cls == cls) return node[cell][i];
      return -1;
    };
    for (size_t a = 0; a < adj_.size(); ++a) {
      Adj& e = adj_[a];
      for (const PieceRec& r : cells_[e.a].pieces) {
        if (r.state == PieceState::Empty) continue;
        const PieceRec* other = piece(e.b, r.cls);
        if (!other || other->state == PieceState::Empty) continue;
        int32_t k = -1;
        for (size_t i = 0; i < e.classes.size(); ++i)
          if (e.classes[i].cls == r.cls) k = int32_t(i);
        if (k < 0) {
          e.classes.push_back({r.cls});
          k = int32_t(e.classes.size()) - 1;
        }
        const int32_t id = g.add_adjacency(node_of(e.a, r.cls), node_of(e.b, r.cls),
                                           e.classes[k].state);
        edges.push_back({int32_t(a), k, id});
      }
    }
  }

  void decide_between_components(CountGraph& g, const std::vector<EdgeRef>& edges) {
    // Join first, across components of H only (a spanning forest of witnesses), then refute
    // what still separates two components.
    const int32_t n = g.pieces();
    std::vector<int32_t> rank(n), parent(n);
    boost::disjoint_sets<int32_t*, int32_t*> h(rank.data(), parent.data());
    for (int32_t i = 0; i < n; ++i) h.make_set(i);
    for (const EdgeRef& r : edges)
      if (g.adjacency_state(r.edge) == AdjacencyState::Joined)
        h.union_set(g.end_a(r.edge), g.end_b(r.edge));
    for (const EdgeRef& r : edges) {
      ClassEdge& ce = adj_[r.adj].classes[r.klass];
      const int32_t x = g.end_a(r.edge), y = g.end_b(r.edge);
      if (ce.tried || h.find_set(x) == h.find_set(y)) continue;
      // A piece not proved connected is refined anyway: its adjacencies are decided on its
      // halves.
      if (g.piece_state(x) != PieceState::Connected || g.piece_state(y) != PieceState::Connected)
        continue;
      ce.tried = true;
      ce.state = try_join(adj_[r.adj], ce.cls, ce);
      if (ce.state == AdjacencyState::Undecided) ce.state = try_refute(adj_[r.adj], ce.cls);
      g.set_adjacency_state(r.edge, ce.state);
      if (ce.state == AdjacencyState::Joined) h.union_set(x, y);
      if (stopped()) break;
    }
  }

  // The open places, and what to refine: boxes of open pieces, and both boxes of an
  // undecided adjacency between two components of H.
  void mark_open(const CountGraph& g, const std::vector<EdgeRef>& edges,
                 std::vector<int32_t>& refine, CountResult& out) {
    const std::vector<int32_t> hc = g.joined_components();
    std::vector<uint8_t> mark(cells_.size(), 0);
    out.open.clear();
    auto note = [&](OpenReason why, uint32_t cls, int32_t cell) {
      if (out.open.size() >= kMaxOpenPlaces) return;
      OpenPlace place{why, cls, {}, {}};
      for (const Interval& x : cells_[cell].box) {
        place.lo.push_back(x.lo_down());
        place.hi.push_back(x.hi_up());
      }
      out.open.push_back(std::move(place));
    };
    std::fill(std::begin(out.open_by_reason), std::end(out.open_by_reason), 0);
    for (size_t c = 0; c < cells_.size(); ++c) {
      if (!cells_[c].alive) continue;
      for (const PieceRec& r : cells_[c].pieces)
        if (r.state == PieceState::Undecided || r.state == PieceState::Nonempty) {
          ++out.open_by_reason[int(r.why)];
          if (!mark[c]) note(r.why, r.cls, int32_t(c));
          mark[c] = 1;
        }
    }
    for (const EdgeRef& r : edges) {
      if (g.adjacency_state(r.edge) != AdjacencyState::Undecided) continue;
      const int32_t x = g.end_a(r.edge), y = g.end_b(r.edge);
      if (hc[x] == hc[y]) continue;
      const Adj& e = adj_[r.adj];
      ++out.open_by_reason[int(OpenReason::Adjacency)];
      // An end not proved connected is refined for itself, and the adjacency decided on its
      // halves: the other box need not be cut for it.
      if (g.piece_state(x) != PieceState::Connected || g.piece_state(y) != PieceState::Connected)
        continue;
      if (!mark[e.a]) note(OpenReason::Adjacency, e.classes[r.klass].cls, e.a);
      mark[e.a] = mark[e.b] = 1;
    }
    for (size_t c = 0; c < cells_.size(); ++c)
      if (mark[c]) refine.push_back(int32_t(c));
  }

  void bounds_and_open(CountResult& out, bool) {
    rebuild_adjacencies();
    std::vector<int32_t> unused;
    decide_adjacencies_and_bound(unused, out);
  }

  // ----- refinement
  bool bisect(int32_t id) {
    const Box box = cells_[id].box;
    int var = -1;
    double rel = 0;
    std::vector<int> vars = cells_[id].split_in;
    for (int pass = 0; pass < 2 && var < 0; ++pass) {
      if (pass == 1 || vars.empty()) {
        vars.clear();
        for (int v = 0; v < nv_; ++v) vars.push_back(v);
      }
      for (int v : vars) {
        const double r = box[v].width_up() / domain_width_[v];
        if (r > config_.min_width && r > rel) rel = r, var = v;
      }
    }
    if (var < 0) return false;
    const double mid = box[var].mid();
    cells_[id].alive = false;
    const int32_t node = cells_[id].node;
    if (node < 0 || node >= int32_t(tree_.size()) || tree_[node].leaf() != id)
      throw std::logic_error("count: a box without its leaf in the tree");
    const int32_t first = int32_t(tree_.size());
    for (int half = 0; half < 2; ++half) {
      Cell c;
      c.box = box;
      c.cut_var = int8_t(var);
      if (half == 0)
        c.box[var].set_hull(box[var].lo_down(), mid);
      else
        c.box[var].set_hull(mid, box[var].hi_up());
      SearchNode leaf;
      leaf.fate = LeafFate::Discarded;
      // With a gap (proofs/checker_gap.h): the certificate's checker refutes the closed
      // slabs the contraction removed.
      if (!gap_.contract(c.box)) {  // else no solution in this half
        c.node = first + half;
        c.origin = c.box;
        cells_[id].child[half] = int32_t(cells_.size());
        leaf.index = int32_t(cells_.size());
        leaf.fate = LeafFate::Undecided;
        cells_.push_back(std::move(c));
      }
      tree_.push_back(leaf);
    }
    tree_[node].set_children(var, mid, first);
    cells_[id].split_var = var;
    cells_[id].split_at = mid;
    return true;
  }

 public:
  // The decisions as they stand, with what proves each (the certificate's count records).
  std::shared_ptr<CountRecords> records() const {
    auto out = std::make_shared<CountRecords>();
    out->first_cover = first_cover_;
    const int n = m_.n();
    auto pairs = [](const Box& b) {
      std::vector<double> v;
      for (const Interval& x : b) v.push_back(x.lo_down()), v.push_back(x.hi_up());
      return v;
    };
    for (const Cell& c : cells_) {
      CountCellRecord r;
      r.fit = c.fit;
      r.origin = pairs(c.origin);
      r.box = pairs(c.box);
      if (c.fit == CountCellRecord::Charted || c.fit == CountCellRecord::Void) {
        r.w = c.chart.w;
        r.w_tilde = pairs(c.chart.w_tilde);
      }
      r.split_var = c.split_var;
      r.split_at = c.split_at;
      r.child[0] = c.child[0], r.child[1] = c.child[1];
      r.alive = c.alive;
      for (const PieceRec& pr : c.pieces) {
        CountCellRecord::Piece q{pr.cls, pr.state, pr.empty_by, pr.connected_by, {}, {}, {}};
        if (!pr.point.u.empty()) {
          q.point_w = pr.point.w_vars;
          q.point_u = pr.point.u;
          q.point_hint = pairs(pr.point.w);
        } else if (pr.state == PieceState::Connected && !c.solution &&
                   c.fit == CountCellRecord::Charted) {
          // The whole graph over U, in one class: any u of U is a point (its middle).
          q.point_w = c.chart.w;
          for (int u : c.chart.u) q.point_u.push_back(c.box[u].mid());
          for (int j = 0; j < n; ++j)
            q.point_hint.push_back(c.box[c.chart.w[j]].lo_down()),
                q.point_hint.push_back(c.box[c.chart.w[j]].hi_up());
        }
        r.pieces.push_back(std::move(q));
      }
      out->cells.push_back(std::move(r));
    }
    for (const Adj& e : adj_) {
      if (!cells_[e.a].alive || !cells_[e.b].alive) continue;
      for (const ClassEdge& ce : e.classes) {
        if (ce.state == AdjacencyState::Refuted) {
          out->refuted.push_back({e.a, e.b, ce.cls});
        } else if (ce.state == AdjacencyState::Joined) {
          CountRecords::Joined j{e.a, e.b, ce.cls, ce.shift, ce.point.u.empty(), {}, {}, {}, {}};
          if (!j.bridge) {
            j.w = ce.point.w_vars;
            j.u = ce.point.u;
            j.hint = pairs(ce.point.w);
          } else {
            j.w = ce.bridge.w;
            j.w_tilde = pairs(ce.bridge.w_tilde);
          }
          out->joined.push_back(std::move(j));
        }
      }
    }
    return out;
  }

 private:

  Model& m_;
  const CountConfig& config_;
  const FactorGradients& fg_;
  const FactorGradients* atoms_;  // the constraints' atoms (null without constraints)
  ModelEvaluator ev_;
  EquationContractor contractor_;
  ConstraintChecker check_;
  ConstraintReducer reducer_;
  PointConstraints feasible_;  // every point feasible (check_ when there are constraints)
  CheckerGapContractor gap_{contractor_};
  long first_cover_ = 0;
  HsWorkspace ws_;
  int nv_;
  Interval two_pi_;
  std::vector<bool> periodic_;
  std::vector<double> domain_width_;
  std::vector<Cell> cells_;
  std::vector<Adj> adj_;
  std::unordered_map<uint64_t, int32_t> adj_index_;  // (a << 32 | b) -> index in adj_
  std::vector<SearchNode> tree_;
  long star_boxes_ = 0;
  int separation_bound_ = 0;
};

}  // namespace

CountResult count_aspects(Model& model, const CountConfig& config) {
  if (!model.user_factors.empty())
    throw std::invalid_argument(
        "count: models with `factor` statements are not counted yet (a user factor may vanish "
        "at nonsingular configurations, so its classes need not be the aspects' classes)");
  const auto start = std::chrono::steady_clock::now();
  AspectsConfig ac;
  ac.eps = config.eps;
  ac.threads = config.threads;
  ac.keep_link_proofs = false;
  ac.stop = config.stop;
  ac.certificate = config.certificate;
  ac.keep_link_proofs = config.certificate != nullptr;  // the writer's finish() needs them
  // Cut off the middle: a middle cut lies on a model's plane of symmetry (x2 = 0 on RRRRR),
  // where singular curves meet the cut and the seam q = ±π in one point. The pieces at such a
  // point are slivers no interval test decides (a class present only in the ulp by which a
  // box's outward end passes π): the refinement never ended there.
  ac.split_fraction = 31.0 / 64;
  AspectsResult solved = compute_aspects(model, ac);
  if (config.first_cover_done) config.first_cover_done(solved, config.first_cover_data);
  std::vector<int> nodes;
  for (const Factor& f : solved.factors) nodes.push_back(f.node);
  // The derivatives are added to the DAG before the counter's evaluator exists.
  FactorGradients fg(model, nodes);
  std::unique_ptr<FactorGradients> atoms;
  if (!model.constraints.empty())
    atoms = std::make_unique<FactorGradients>(model, model.constraint_atoms);
  Counter counter(model, config, fg, atoms.get());
  counter.add_first_cover(solved);
  const long first_cover_boxes = solved.boxes.size();
  // The counter holds its own copies: the solve's go before the refinement needs memory.
  std::vector<SearchNode>().swap(solved.tree);
  solved.boxes.release();
  CountResult out = counter.run();
  if (config.certificate || config.keep_records) out.records = counter.records();
  out.separation_bound = solved.separation.lower_bound;
  out.first_cover_boxes = first_cover_boxes;
  for (const Factor& f : solved.factors) {
    out.factor_text.push_back(f.text + " (" + f.origin + ")");
    out.factor_origin.push_back(f.origin);
  }
  out.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace aspects
