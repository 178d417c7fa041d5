#include "piece_path.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <set>

#include "counting/chart.h"
#include "counting/star_test.h"
#include "hansen_sengupta.h"
#include "strong_regularity.h"
#include "model/determinant_factors.h"
#include "results/point_command.h"
#include "results/pose.h"
#include "results/result_index.h"

namespace aspects {

std::string class_signs(uint32_t cls, int factors) {
  std::string s;
  for (int i = 0; i < factors; ++i) s += (cls >> i) & 1 ? '+' : '-';
  return s.empty() ? "." : s;
}

CountDirectory load_count_directory(const std::string& dir) {
  CountDirectory d;
  d.pieces = read_count_pieces(dir);
  d.directory = dir;
  const std::string what = dir + "/" + kCountPiecesName;
  set_working_precision(d.pieces.precision_bits);
  try {
    d.model = parse_model(d.pieces.model_source, d.pieces.model_file);
  } catch (const ModelError& e) {
    throw IndexError(what + ": the recorded model does not parse: " + e.what());
  }
  // Its pieces are star-shaped with the constraints' atoms among their constraints; the
  // segments proved here know only the factors and faces, and could leave the feasible set.
  if (!d.model.constraints.empty())
    throw IndexError(what + ": the count's model has `constraint` statements; `aspects path` "
                     "does not plan through the pieces of such a count yet");
  if (d.model.vars.size() != d.pieces.nv || uint32_t(d.model.n()) != d.pieces.n)
    throw IndexError(what + ": the recorded model has " + std::to_string(d.model.vars.size()) +
                     " variables, the file " + std::to_string(d.pieces.nv));
  // The classes' bits are the factors' order: the model's factors must be the count's.
  std::vector<std::string> texts;
  for (const Factor& f : determinant_factors(d.model)) {
    texts.push_back(f.text + " (" + f.origin + ")");
    d.factor_nodes.push_back(f.node);
    d.factor_origins.push_back(f.origin);
  }
  if (texts != d.pieces.factors)
    throw IndexError(what + ": the model's determinant factors are not the count's (written by "
                     "another version of aspects?): re-run `aspects count --out`");
  for (const CountJoin& j : d.pieces.joins)
    for (uint32_t v = 0; v < d.pieces.nv; ++v)
      if (j.shift[v] != 0 && !d.model.vars[v].periodic)
        throw IndexError(what + ": a join is shifted on a variable that is not periodic");
  return d;
}

namespace {

constexpr double kTau = 1.01;

Interval two_pi() {
  Interval t(0.0);
  mpfi_const_pi(t.get());
  mpfi_mul_ui(t.get(), t.get(), 2);
  return t;
}

// A configuration proved: its enclosure (model order).
struct Config {
  std::vector<double> lo, hi;
};

class Planner {
 public:
  Planner(const CountDirectory& d, ModelEvaluator& ev, const FactorGradients& fg)
      : P_(d.pieces), m_(d.model), ev_(ev), fg_(fg), nv_(int(P_.nv)), n_(int(P_.n)) {
    for (size_t c = 0; c < P_.cells.size(); ++c) {
      cell_index_[P_.cells[c].id] = int(c);
      for (size_t k = 0; k < P_.cells[c].pieces.size(); ++k) {
        node_of_[{int(c), P_.cells[c].pieces[k].cls}] = int(nodes_.size());
        nodes_.push_back({int(c), int(k)});
      }
    }
    adj_.resize(nodes_.size());
    for (size_t j = 0; j < P_.joins.size(); ++j) {
      const CountJoin& J = P_.joins[j];
      const int a = node(cell_index_.at(J.a), J.cls), b = node(cell_index_.at(J.b), J.cls);
      if (a < 0 || b < 0) continue;
      adj_[a].push_back({int(j), b});
      adj_[b].push_back({int(j), a});
    }
  }

  PiecePathResult plan(const std::vector<double>& from, const std::vector<double>& to,
                       int64_t want) {
    PiecePathResult out;
    std::vector<Anchor> starts = anchors_of(from, out.start_cells);
    std::vector<Anchor> goals = anchors_of(to, out.goal_cells);
    auto classes = [](const std::vector<Anchor>& as) {
      std::set<uint32_t> s;
      for (const Anchor& a : as) s.insert(a.cls);
      return std::vector<uint32_t>(s.begin(), s.end());
    };
    out.start_classes = classes(starts);
    out.goal_classes = classes(goals);
    if (starts.empty()) return out.outcome = PiecePathOutcome::StartNowhere, out;
    if (goals.empty()) return out.outcome = PiecePathOutcome::GoalNowhere, out;
    std::vector<uint32_t> common;
    std::set_intersection(out.start_classes.begin(), out.start_classes.end(),
                          out.goal_classes.begin(), out.goal_classes.end(),
                          std::back_inserter(common));
    if (want >= 0) {
      const bool in_start = std::count(out.start_classes.begin(), out.start_classes.end(), want);
      const bool in_goal = std::count(out.goal_classes.begin(), out.goal_classes.end(), want);
      if (!in_start || !in_goal) return out.outcome = PiecePathOutcome::ClassAbsent, out;
      common = {uint32_t(want)};
    }
    if (common.empty()) return out.outcome = PiecePathOutcome::DifferentClasses, out;
    // The classes whose pieces join a start to a goal (the count's joins, before any proof).
    std::vector<uint32_t> joined;
    for (uint32_t c : common)
      if (!route(starts, goals, c).steps.empty()) joined.push_back(c);
    if (joined.empty())
      return out.outcome = P_.exact() ? PiecePathOutcome::DifferentAspects
                                      : PiecePathOutcome::NotJoined,
             out;
    for (uint32_t c : joined) {
      if (out.outcome == PiecePathOutcome::Found) break;
      // A point or bridge that is not proved again is left out, and a route sought again.
      for (int attempt = 0; attempt < 64; ++attempt) {
        const Route r = route(starts, goals, c);
        if (r.steps.empty()) break;
        if (certify(r, starts, goals, out)) {
          out.outcome = PiecePathOutcome::Found;
          out.cls = c;
          break;
        }
      }
    }
    if (out.outcome != PiecePathOutcome::Found) {
      out.outcome = PiecePathOutcome::ProofFailed;
      if (out.failure.empty()) out.failure = "no route through the pieces could be proved again";
      return out;
    }
    for (uint32_t c : common)
      if (c != out.cls) out.other_classes.push_back(c);
    return out;
  }

 private:
  struct NodeRef {
    int cell, piece;
  };
  struct Edge {
    int join, to;
  };
  // A configuration of a pose proved in a connected piece (node), with the turns that bring
  // the pose into the cell's box.
  struct Anchor {
    int node;
    uint32_t cls;
    Config config;           // the pose (as given) and its command enclosure
    std::vector<int> turns;  // per variable: pose + 2π·turns lies in the box
  };
  // One piece of a route, entered through join `join` (-1: the first) from the previous.
  struct Step {
    int node, join;
  };
  struct Route {
    std::vector<Step> steps;  // empty: none
    int start = -1, goal = -1;  // the anchors at its ends
  };

  int node(int cell, uint32_t cls) const {
    const auto it = node_of_.find({cell, cls});
    return it == node_of_.end() ? -1 : it->second;
  }
  const CountPieceCell& cell_of(int node) const { return P_.cells[nodes_[node].cell]; }
  const CountPiece& piece_of(int node) const {
    return cell_of(node).pieces[nodes_[node].piece];
  }

  Box box_of(const CountPieceCell& c) const {
    Box b(nv_);
    for (int v = 0; v < nv_; ++v) b[v].set_hull(c.box[2 * v], c.box[2 * v + 1]);
    return b;
  }

  bool in_domain(const Config& x) const {
    for (int v = 0; v < nv_; ++v)
      if (!m_.vars[v].periodic &&
          !(x.lo[v] >= m_.vars[v].domain.lo_down() && x.hi[v] <= m_.vars[v].domain.hi_up()))
        return false;
    return true;
  }

  // The class of every point of the enclosure: -1 unless every factor has a certain sign.
  int64_t class_of(const Config& x) {
    Box z(nv_);
    for (int v = 0; v < nv_; ++v) z[v].set_hull(x.lo[v], x.hi[v]);
    std::vector<Interval> g;
    if (!fg_.values(ev_, z, g)) return -1;
    uint32_t cls = 0;
    for (size_t i = 0; i < g.size(); ++i) {
      if (g[i].certainly_pos()) cls |= uint32_t(1) << i;
      else if (!g[i].certainly_neg()) return -1;
    }
    return cls;
  }

  static bool inside(const Config& x, const Box& box, const std::vector<int>& vars) {
    for (int v : vars)
      if (!(x.lo[v] >= box[v].lo_down() && x.hi[v] <= box[v].hi_up())) return false;
    return true;
  }
  std::vector<int> all_vars() const {
    std::vector<int> v(nv_);
    for (int i = 0; i < nv_; ++i) v[i] = i;
    return v;
  }

  // Iteration (9) of Hansen–Sengupta at the u-point, w unknown from the hint (inflated as
  // check_cert inflates a point's hint): a unique zero in the iterate, enclosed by the image.
  bool prove_point(const std::vector<int>& w, const std::vector<double>& u,
                   const std::vector<double>& hint, Config& out) {
    const std::vector<int> uv = chart_complement(m_, w);
    Box z(nv_);
    out.lo.assign(nv_, 0);
    out.hi.assign(nv_, 0);
    for (int k = 0; k < n_; ++k) {
      z[uv[k]].set_point(u[k]);
      out.lo[uv[k]] = out.hi[uv[k]] = u[k];
    }
    for (int j = 0; j < n_; ++j) {
      const double lo = hint[2 * j], hi = hint[2 * j + 1];
      const double r = 0.1 * (hi - lo) + 1e-13 * (1 + std::max(std::fabs(lo), std::fabs(hi)));
      z[w[j]].set_hull(lo - r, hi + r);
    }
    ExistenceProof proof;
    if (prove_existence(ev_, z, kTau, 12, proof, ws_, false, nullptr, &w) != Existence::Proved)
      return false;
    for (int j = 0; j < n_; ++j) {
      out.lo[w[j]] = proof.image[j].lo_down();
      out.hi[w[j]] = proof.image[j].hi_up();
    }
    return true;
  }

  // A recorded point proved again as a point of W_cls in `box`.
  bool prove_in(const std::vector<int>& w, const std::vector<double>& u,
                const std::vector<double>& hint, const Box& box, uint32_t cls, Config& out) {
    return prove_point(w, u, hint, out) && inside(out, box, all_vars()) && in_domain(out) &&
           class_of(out) == int64_t(cls);
  }

  // The configurations of a pose proved in a connected piece of a cell: a command at the
  // pose proved inside the box as `query` proves one (Newton, then Hansen–Sengupta at the
  // point), one per cell, its class by the factors' enclosures there.
  std::vector<Anchor> anchors_of(const std::vector<double>& pose, long& cells) {
    std::vector<Anchor> out;
    cells = 0;
    std::vector<double> lo(nv_), hi(nv_);
    for (size_t c = 0; c < P_.cells.size(); ++c) {
      const CountPieceCell& cell = P_.cells[c];
      for (int v = 0; v < nv_; ++v) lo[v] = cell.box[2 * v], hi[v] = cell.box[2 * v + 1];
      std::vector<long> turns;
      if (pose_in_box(m_, pose, lo.data(), hi.data(), &turns) != Membership::Inside) continue;
      ++cells;
      const PointCommand pc = certified_command(ev_, lo.data(), hi.data(), pose, kTau, ws_);
      if (pc.status != PointCommandStatus::Certified) continue;
      Anchor a;
      a.config.lo.assign(nv_, 0);
      a.config.hi.assign(nv_, 0);
      a.turns.assign(nv_, 0);
      for (int j = 0; j < n_; ++j) {
        a.config.lo[m_.pose[j]] = a.config.hi[m_.pose[j]] = pose[j];
        a.turns[m_.pose[j]] = int(turns[j]);
        a.config.lo[m_.command[j]] = pc.lo[j];
        a.config.hi[m_.command[j]] = pc.hi[j];
      }
      if (!inside(a.config, box_of(cell), m_.command) || !in_domain(a.config)) continue;
      const int64_t cls = class_of(a.config);
      if (cls < 0) continue;
      a.node = node(int(c), uint32_t(cls));
      if (a.node < 0) continue;
      a.cls = uint32_t(cls);
      out.push_back(std::move(a));
    }
    return out;
  }

  // The fewest pieces from a start anchor to a goal anchor of class c, through joins not
  // failed; empty when there is none.
  Route route(const std::vector<Anchor>& starts, const std::vector<Anchor>& goals, uint32_t c) {
    std::vector<int> from_join(nodes_.size(), -2), prev(nodes_.size(), -1),
        start_of(nodes_.size(), -1);
    std::deque<int> queue;
    for (size_t i = 0; i < starts.size(); ++i)
      if (starts[i].cls == c && from_join[starts[i].node] == -2 &&
          !dead_node_.count(starts[i].node)) {
        from_join[starts[i].node] = -1;
        start_of[starts[i].node] = int(i);
        queue.push_back(starts[i].node);
      }
    std::map<int, int> goal_at;  // node -> goal anchor
    for (size_t i = 0; i < goals.size(); ++i)
      if (goals[i].cls == c && !goal_at.count(goals[i].node)) goal_at[goals[i].node] = int(i);
    while (!queue.empty()) {
      const int x = queue.front();
      queue.pop_front();
      if (goal_at.count(x)) {
        Route r;
        for (int y = x; y >= 0; y = prev[y]) r.steps.push_back({y, from_join[y]});
        std::reverse(r.steps.begin(), r.steps.end());
        r.start = start_of[r.steps.front().node];
        r.goal = goal_at[x];
        return r;
      }
      for (const Edge& e : adj_[x]) {
        if (from_join[e.to] != -2 || dead_join_.count(e.join) || dead_node_.count(e.to)) continue;
        from_join[e.to] = e.join;
        prev[e.to] = x;
        queue.push_back(e.to);
      }
    }
    return {};
  }

  // The inward enclosure of box + 2πk: every point of it lies in box + 2πk. False when it
  // is empty (a box narrower than the rounding).
  bool shifted_inward(const Box& box, const std::vector<int8_t>& k, Box& b) const {
    b = box;
    for (int v = 0; v < nv_; ++v) {
      if (k[v] == 0) continue;
      Interval t;
      mpfi_mul_si(t.get(), two_pi_.get(), k[v]);
      Interval lo, hi;
      mpfi_add_d(lo.get(), t.get(), box[v].lo_down());
      mpfi_add_d(hi.get(), t.get(), box[v].hi_up());
      if (!(lo.hi_up() <= hi.lo_down())) return false;
      b[v].set_hull(lo.hi_up(), hi.lo_down());
    }
    return true;
  }
  Box hull_outward(const Box& a, const Box& b, const std::vector<int8_t>& k) const {
    Box h = a;
    for (int v = 0; v < nv_; ++v) {
      double lo = b[v].lo_down(), hi = b[v].hi_up();
      if (k[v] != 0) {
        Interval t, e;
        mpfi_mul_si(t.get(), two_pi_.get(), k[v]);
        mpfi_add_d(e.get(), t.get(), lo);
        lo = e.lo_down();
        mpfi_add_d(e.get(), t.get(), hi);
        hi = e.hi_up();
      }
      h[v].set_hull(std::min(lo, a[v].lo_down()), std::max(hi, a[v].hi_up()));
    }
    return h;
  }

  // The centre of a Star piece, or a point of a Graph piece (recorded, else the middle of
  // its box's U), proved again in the piece; cached.
  bool piece_point(int nd, Config& out, std::string& why) {
    auto it = point_cache_.find(nd);
    if (it != point_cache_.end()) return out = it->second, true;
    const CountPieceCell& cell = cell_of(nd);
    const CountPiece& p = piece_of(nd);
    const Box box = box_of(cell);
    bool ok;
    if (!p.w_vars.empty()) {
      // A star's centre is a u-point of its box's chart (the test is about it there).
      ok = (p.how != CountPiece::Star || p.w_vars == cell.w) &&
           prove_in(p.w_vars, p.u, p.hint, box, p.cls, out);
    } else {
      const std::vector<int> uv = chart_complement(m_, cell.w);
      std::vector<double> u, hint;
      for (int v : uv) u.push_back(box[v].mid());
      for (int v : cell.w) hint.push_back(box[v].lo_down()), hint.push_back(box[v].hi_up());
      ok = prove_in(cell.w, u, hint, box, p.cls, out);
    }
    if (!ok) {
      why = "the " + std::string(p.how == CountPiece::Star ? "centre" : "point") + " of box " +
            std::to_string(cell.id) + "'s piece of class " + class_signs(p.cls, fg_.factors()) +
            " was not proved again";
      return false;
    }
    point_cache_[nd] = out;
    return true;
  }

  // The segments inside a piece proved again on its box B as recorded. First a chart on B
  // (w unknown, unique in W̃ ⊇ B_w, w(U) ⊆ R; every point of B on V is on its graph). Then
  // either the whole graph over U lies in W_s: U × R in the domain, and on it every factor
  // of the class's sign, or P2 (Fx and Fq regular: every factor, a determinant or a diagonal
  // entry of a triangular Jacobian, nonzero, so of one sign along the graph, the sign of the
  // points proved on it) — then any segment of U lifts into W_s; or, as the count proved a
  // star, B in the domain and the star-shaped test about the piece's centre, with the faces
  // of B_w that R crosses and the factors not of one sign on B — then any segment from the
  // centre to a point of the piece lifts into it.
  bool piece_connected(int nd, std::string& why) {
    auto it = connected_cache_.find(nd);
    if (it != connected_cache_.end()) return it->second || (why = connected_why_[nd], false);
    const CountPieceCell& cell = cell_of(nd);
    const CountPiece& p = piece_of(nd);
    std::string fail;
    const bool ok = segments_hold(cell, p, nd, fail);
    if (!ok)
      why = "box " + std::to_string(cell.id) + "'s piece of class " +
            class_signs(p.cls, fg_.factors()) + " was not proved connected again (" + fail + ")";
    connected_cache_[nd] = ok;
    connected_why_[nd] = why;
    return ok;
  }

  bool in_domain(const Box& b) const {
    for (int v = 0; v < nv_; ++v)
      if (!m_.vars[v].periodic && !m_.vars[v].domain.contains(b[v])) return false;
    return true;
  }

  bool of_class(const std::vector<Interval>& g, uint32_t cls) const {
    for (size_t i = 0; i < g.size(); ++i)
      if (!((cls >> i) & 1 ? g[i].certainly_pos() : g[i].certainly_neg())) return false;
    return true;
  }

  bool segments_hold(const CountPieceCell& cell, const CountPiece& p, int nd, std::string& fail) {
    const Box box = box_of(cell);
    Chart chart;
    if (prove_chart(ev_, box, cell.w, ws_, chart) != ChartVerdict::Proved)
      return fail = "no chart", false;
    Box z = box;
    for (int j = 0; j < n_; ++j) z[chart.w[j]] = chart.w_range[j];
    std::vector<Interval> g;
    if (in_domain(z) && ((fg_.values(ev_, z, g) && of_class(g, p.cls)) || regular_on(z))) {
      proof_[nd] = CountPiece::Graph;
      return true;
    }
    // The star-shaped test, as the count ran it.
    if (!in_domain(box)) return fail = "the box leaves the domain", false;
    std::vector<StarConstraint> tests;
    for (int j = 0; j < n_; ++j) {
      const int v = chart.w[j];
      if (chart.w_range[j].lo_down() < box[v].lo_down())
        tests.push_back({StarConstraint::WLower, j, 1, box[v].lo_down()});
      if (chart.w_range[j].hi_up() > box[v].hi_up())
        tests.push_back({StarConstraint::WUpper, j, 1, box[v].hi_up()});
    }
    const bool defined = fg_.values(ev_, box, g);
    for (int i = 0; i < fg_.factors(); ++i) {
      const bool positive = (p.cls >> i) & 1;
      if (defined && (positive ? g[i].certainly_pos() : g[i].certainly_neg())) continue;
      tests.push_back({StarConstraint::Factor, i, positive ? 1 : -1, 0});
    }
    if (p.w_vars.empty())
      return fail = "its graph is not of one class, and it has no centre", false;
    if (p.w_vars != cell.w) return fail = "its centre is not in the box's chart", false;
    Config centre;
    std::string why;
    if (!piece_point(nd, centre, why)) return fail = "its centre", false;
    std::vector<double> v;
    std::vector<Interval> wv;
    for (int u : chart.u) v.push_back(centre.lo[u]);
    for (int w : chart.w) wv.emplace_back(centre.lo[w], centre.hi[w]);
    long boxes = 0;
    if (star_test(ev_, fg_, chart, z, tests, v, wv, StarLimits{}, ws_, boxes) !=
        StarVerdict::StarShaped)
      return fail = "star-shaped test", false;
    proof_[nd] = CountPiece::Star;
    return true;
  }

  // P2 on the box: Fx and Fq strongly regular over it.
  bool regular_on(const Box& box) {
    IMatrix J;
    return ev_.jacobian_x(box, J) == EvalStatus::Defined && strongly_regular(J) &&
           ev_.jacobian_q(box, J) == EvalStatus::Defined && strongly_regular(J);
  }

  // A join proved again: its point in both boxes, or its bridge chart.
  bool join_holds(int j, Config& point, std::string& why) {
    const CountJoin& J = P_.joins[j];
    const Box a = box_of(P_.cells[cell_index_.at(J.a)]), b = box_of(P_.cells[cell_index_.at(J.b)]);
    bool ok = false;
    if (!J.bridge) {
      Box b_shifted;
      ok = prove_in(J.w, J.u, J.hint, a, J.cls, point) &&
           shifted_inward(b, J.shift, b_shifted) && inside(point, b_shifted, all_vars());
    } else {
      const Box hull = hull_outward(a, b, J.shift);
      Chart chart;
      if (prove_chart(ev_, hull, J.w, ws_, chart) == ChartVerdict::Proved) {
        Box z = hull;
        ok = true;
        for (int k = 0; k < n_; ++k) {
          const int v = chart.w[k];
          z[v] = chart.w_range[k];
          if (!m_.vars[v].periodic && !m_.vars[v].domain.contains(z[v])) ok = false;
        }
        std::vector<Interval> g;
        ok = ok && fg_.values(ev_, z, g);
        for (size_t i = 0; ok && i < g.size(); ++i)
          ok = (J.cls >> i) & 1 ? g[i].certainly_pos() : g[i].certainly_neg();
      }
    }
    if (!ok)
      why = std::string(J.bridge ? "the bridge" : "the join point") + " between boxes " +
            std::to_string(J.a) + " and " + std::to_string(J.b) + " was not proved again";
    return ok;
  }

  PieceWaypoint waypoint(PieceWaypoint::Kind kind, int cell, const Config& x,
                         const std::vector<int>& turns) const {
    return {kind, cell, x.lo, x.hi, turns};
  }

  // The route's waypoints and segments, every point and bridge proved again; false (with
  // the failing node or join marked dead) when one is not.
  bool certify(const Route& route, const std::vector<Anchor>& starts,
               const std::vector<Anchor>& goals, PiecePathResult& out) {
    const std::vector<Step>& r = route.steps;
    std::vector<PieceWaypoint> wps;
    std::vector<PieceSegment> segs;
    int point_joins = 0, bridges = 0;
    std::string why;
    for (const Step& st : r)
      if (!piece_connected(st.node, why)) {
        dead_node_.insert(st.node);
        out.failure = why;
        return false;
      }
    const Anchor& s = starts[route.start];
    // The frame of the first box: the start pose lies in it at turns s.turns, so its
    // configurations are at −s.turns in the path's coordinates.
    std::vector<int> T(nv_);
    for (int v = 0; v < nv_; ++v) T[v] = -s.turns[v];
    wps.push_back(waypoint(PieceWaypoint::Start, cell_of(s.node).id, s.config,
                           std::vector<int>(nv_, 0)));
    // Adds the segment to the last waypoint inside piece nd (how: its proof).
    auto star = [&](int nd) { return proof_.at(nd) == CountPiece::Star; };
    auto segment_in = [&](int nd) {
      segs.push_back({star(nd) ? PieceSegment::Star : PieceSegment::Graph,
                      cell_of(nd).id, chart_complement(m_, cell_of(nd).w)});
    };
    for (size_t i = 0; i < r.size(); ++i) {
      const int nd = r[i].node;
      if (i > 0) {
        const CountJoin& J = P_.joins[r[i].join];
        Config jp;
        if (!join_holds(r[i].join, jp, why)) {
          dead_join_.insert(r[i].join);
          out.failure = why;
          return false;
        }
        const bool forward = J.a == cell_of(r[i - 1].node).id;
        std::vector<int> T_next = T;
        for (int v = 0; v < nv_; ++v) T_next[v] += forward ? J.shift[v] : -J.shift[v];
        if (!J.bridge) {
          // The point is in a's frame: before the crossing (forward) or after it.
          const std::vector<int>& Ta = forward ? T : T_next;
          segment_in(r[i - 1].node);
          wps.push_back(waypoint(PieceWaypoint::Join, cell_of(nd).id, jp, Ta));
          ++point_joins;
        } else {
          // From the previous piece's point to this one's, straight in the bridge's u.
          Config q;
          if (!piece_point(nd, q, why)) {
            dead_node_.insert(nd);
            out.failure = why;
            return false;
          }
          segs.push_back({PieceSegment::Bridge, cell_of(r[i - 1].node).id,
                          chart_complement(m_, J.w)});
          wps.push_back(waypoint(star(nd) ? PieceWaypoint::Centre : PieceWaypoint::Point,
                                 cell_of(nd).id, q, T_next));
          ++bridges;
        }
        T = T_next;
      }
      // Inside piece nd: through its centre (Star), or to its point before a bridge.
      const bool last = i + 1 == r.size();
      const bool bridge_next = !last && r[i + 1].join >= 0 && P_.joins[r[i + 1].join].bridge;
      const bool at_point = (wps.back().kind == PieceWaypoint::Point ||
                             wps.back().kind == PieceWaypoint::Centre) &&
                            wps.back().cell == cell_of(nd).id;
      if (!at_point && (star(nd) || bridge_next)) {
        Config q;
        if (!piece_point(nd, q, why)) {
          dead_node_.insert(nd);
          out.failure = why;
          return false;
        }
        segment_in(nd);
        wps.push_back(waypoint(star(nd) ? PieceWaypoint::Centre : PieceWaypoint::Point,
                               cell_of(nd).id, q, T));
      }
      if (last) {
        const Anchor& g = goals[route.goal];
        std::vector<int> turns = T;
        for (int v = 0; v < nv_; ++v) turns[v] += g.turns[v];
        segment_in(nd);
        wps.push_back(waypoint(PieceWaypoint::Goal, cell_of(nd).id, g.config, turns));
      }
    }
    // A segment of a Star piece must have the centre at one end (the test is about it).
    for (size_t k = 0; k < segs.size(); ++k)
      if (segs[k].how == PieceSegment::Star && wps[k].kind != PieceWaypoint::Centre &&
          wps[k + 1].kind != PieceWaypoint::Centre) {
        out.failure = "internal: a segment of a star-shaped piece misses its centre";
        return false;
      }
    out.waypoints = std::move(wps);
    out.segments = std::move(segs);
    std::set<int> distinct;
    for (const Step& st : r) distinct.insert(st.node);
    out.pieces = int(distinct.size());
    out.point_joins = point_joins;
    out.bridges = bridges;
    return true;
  }

  const CountPieces& P_;
  const Model& m_;
  ModelEvaluator& ev_;
  const FactorGradients& fg_;
  int nv_, n_;
  Interval two_pi_ = two_pi();
  HsWorkspace ws_;
  std::map<int32_t, int> cell_index_;
  std::map<std::pair<int, uint32_t>, int> node_of_;
  std::vector<NodeRef> nodes_;
  std::vector<std::vector<Edge>> adj_;
  std::set<int> dead_node_, dead_join_;
  std::map<int, Config> point_cache_;
  std::map<int, bool> connected_cache_;
  std::map<int, CountPiece::How> proof_;  // how each piece was proved again
  std::map<int, std::string> connected_why_;
};

}  // namespace

PiecePathResult plan_piece_path(const CountDirectory& dir, ModelEvaluator& ev,
                                const FactorGradients& fg, const std::vector<double>& from,
                                const std::vector<double>& to, int64_t cls) {
  return Planner(dir, ev, fg).plan(from, to, cls);
}

}  // namespace aspects
