#include "generalized_aspects.h"

#include <chrono>
#include <cmath>
#include <string>

#include "constraints.h"
#include "determinant_factors.h"
#include "model_eval.h"
#include "strong_regularity.h"

namespace aspects {

namespace {

// Algorithm 1's steps for the NCSP (4): f = 0, det Fx ≠ 0, det Fq ≠ 0.
class AspectsSearch : public BranchAndPruneSteps {
 public:
  AspectsSearch(const Model& m, const AspectsConfig& cfg, AspectsResult& out)
      : m_(m), cfg_(cfg), out_(out), ev_(m), constraints_(m, ev_), n_(m.n()),
        nv_(int(m.vars.size())) {
    for (const auto& f : out_.factors) factor_nodes_.push_back(f.node);
    factor_prog_ = m.dag.closure(factor_nodes_);
    for (int i = 0; i < n_; ++i) hints_.push_back("eq" + std::to_string(i));
    domain_ = m.initial_box();
  }

  // Prune: contraction (below), recorded for the certificate.
  bool prune(Box& box, int32_t& reason) override {
    cell_ = box;
    if (!contract(box, reason)) {
      if (cfg_.certificate)
        cfg_.certificate->discard(reason < n_ ? hints_[reason].c_str() : "hs");
      return false;
    }
    // Leave a gap between the contraction and the recorded box, so that the closed
    // slabs a checker refutes (certificates/FORMAT.md) really hold no solution.
    for (int v = 0; v < nv_; ++v) {
      double clo = cell_[v].lo_down(), chi = cell_[v].hi_up();
      double lo = box[v].lo_down(), hi = box[v].hi_up();
      double gap = 1e-9 * (chi - clo);
      lo = lo - gap <= clo ? clo : std::nextafter(lo - gap, -INFINITY);
      hi = hi + gap >= chi ? chi : std::nextafter(hi + gap, INFINITY);
      box[v].set_hull(lo, hi);
      if ((lo > clo || hi < chi) && cfg_.certificate) cfg_.certificate->contraction(v, lo, hi);
    }
    // Additional constraints (paper 5.4): a box where one certainly fails holds no
    // feasible configuration.
    int violated = -1;
    if (constraints_.evaluate(box, &violated) == Truth::False) {
      if (cfg_.certificate) cfg_.certificate->discard(("c" + std::to_string(violated)).c_str());
      reason = n_ + 1 + violated;
      return false;
    }
    return true;
  }

  // AC3-like fixpoint of HC4-Revise over the equations, then one Hansen–Sengupta
  // contraction of the commands; the result is rounded outward to doubles.
  bool contract(Box& box, int32_t& reason) {
    for (int round = 0; round < 20; ++round) {
      double before = total_width(box);
      for (int i = 0; i < n_; ++i)
        if (!ev_.hc4(i, box)) {
          reason = i;
          return false;
        }
      if (total_width(box) > 0.95 * before) break;
    }
    HsStatus s = hansen_sengupta(ev_, box, true, image_, ws_);
    if (s == HsStatus::NoSolution) {
      reason = n_;  // Hansen–Sengupta proved no zero of f(x,·) in [q] for any x
      return false;
    }
    if (s == HsStatus::Ok)
      for (int j = 0; j < n_; ++j) box[m_.command[j]] = image_[j];
    for (auto& x : box) round_out_to_doubles(x);
    return true;
  }

  void branched(int var, double at) override {
    if (cfg_.certificate) cfg_.certificate->split(var, at);
  }

  // Prove: P1 by iteration (9), the coverage and domain rules, then P2 on the
  // reported box ([x], [q(k+1)]).
  bool prove(const Box& cell, int32_t& index) override {
    last_kind_ = UndecidedKind::NoExistence;
    if (!prove_existence(ev_, cell, cfg_.tau, cfg_.max_newton_iterations, proof_.existence, ws_))
      return false;
    auto& ex = proof_.existence;
    // Coverage: uniqueness in [q̃] must cover the whole cell, or solutions of another
    // branch in the cell would be lost. When the iterate shrank below the cell, try
    // once more from the hull of both, so that the proved box contains the cell.
    if (!covers_cell(ex, cell)) {
      retry_ = cell;
      for (int j = 0; j < n_; ++j) {
        int v = m_.command[j];
        mpfi_union(retry_[v].get(), cell[v].get(), ex.inflated[j].get());
      }
      if (!prove_existence(ev_, retry_, cfg_.tau, 2, ex, ws_) || !covers_cell(ex, cell))
        return false;
    }
    for (int j = 0; j < n_; ++j) {
      int v = m_.command[j];
      // Domain: a command outside its range is not a configuration of the robot. A
      // periodic command may cross its seam: f is 2π-periodic in it (checked by the
      // parser), and the box then stands for its values modulo 2π.
      if (!m_.vars[v].periodic && !domain_[v].contains(ex.image[j])) return false;
    }
    reported_ = cell;
    for (int j = 0; j < n_; ++j) reported_[m_.command[j]] = ex.image[j];
    last_kind_ = UndecidedKind::Singular;
    if (ev_.jacobian_x(reported_, J_) != EvalStatus::Defined ||
        !strongly_regular(J_, &proof_.cx))
      return false;
    if (ev_.jacobian_q(reported_, J_) != EvalStatus::Defined ||
        !strongly_regular(J_, &proof_.cq))
      return false;
    // Inner test: every additional constraint holds on the whole reported box.
    if (constraints_.evaluate(reported_) != Truth::True) {
      last_kind_ = UndecidedKind::Constraint;
      return false;
    }
    index = store(reported_, true);
    if (cfg_.certificate) cfg_.certificate->solution(index, last_signs(), proof_);
    return true;
  }

  int32_t keep_undecided(const Box& box) override {
    int32_t index = store(box, false);
    bool on_constraint = !constraints_.empty() && constraints_.evaluate(box) == Truth::Unknown;
    out_.undecided_kind[index] = on_constraint ? UndecidedKind::Constraint : last_kind_;
    if (cfg_.certificate) cfg_.certificate->undecided(index, last_signs());
    return index;
  }

  // Branch: round robin over the variables wider than eps.
  int choose_split(const Box& box, int parent_split) override {
    for (int s = 1; s <= nv_; ++s) {
      int v = (parent_split + s + nv_) % nv_;
      if (parent_split < 0) v = s - 1;
      if (box[v].width_up() > cfg_.eps) return v;
    }
    return -1;
  }

 private:
  bool covers_cell(const ExistenceProof& ex, const Box& cell) const {
    for (int j = 0; j < n_; ++j)
      if (!ex.inflated[j].contains(cell[m_.command[j]])) return false;
    return true;
  }

  const int8_t* last_signs() const {
    return out_.signs.data() + out_.signs.size() - out_.factors.size();
  }

  static double total_width(const Box& b) {
    double w = 0;
    for (const auto& x : b) w += x.width_up();
    return w;
  }

  int32_t store(const Box& box, bool certified) {
    int32_t index = out_.boxes.push(box);
    out_.certified.push_back(certified);
    out_.undecided_kind.push_back(UndecidedKind::NoExistence);
    // Sign of each factor on the stored box; 0 when its enclosure may vanish.
    Box exact;
    out_.boxes.get(index, exact);
    EvalStatus s = ev_.nodes(factor_prog_, exact);
    for (int f : factor_nodes_)
      out_.signs.push_back(s == EvalStatus::Defined ? int8_t(certain_sign(ev_.value(f))) : 0);
    return index;
  }

  const Model& m_;
  const AspectsConfig& cfg_;
  AspectsResult& out_;
  ModelEvaluator ev_;
  ConstraintChecker constraints_;
  int n_, nv_;
  std::vector<int> factor_nodes_, factor_prog_;
  Box domain_, reported_, retry_, cell_;
  std::vector<std::string> hints_;
  HsWorkspace ws_;
  std::vector<Interval> image_;
  IMatrix J_;
  SolutionProof proof_;
  UndecidedKind last_kind_ = UndecidedKind::NoExistence;
};

}  // namespace

AspectsResult compute_aspects(Model& model, const AspectsConfig& config) {
  auto t0 = std::chrono::steady_clock::now();
  AspectsResult out;
  out.factors = determinant_factors(model);  // adds nodes: before any evaluator exists
  out.boxes = BoxStore(int(model.vars.size()));

  SearchStats stats;
  {
    AspectsSearch search(model, config, out);
    std::function<void()> tick;
    if (config.progress) tick = [&]() { config.progress(stats); };
    Box root = model.initial_box();
    for (auto& x : root) round_out_to_doubles(x);
    if (config.certificate) config.certificate->begin(root, out.factors);
    branch_and_prune(root, search, out.tree, stats, tick);
  }
  out.processed = stats.processed;
  out.solutions = stats.solutions;
  out.undecided = stats.undecided;
  out.discarded = stats.discarded;

  // 4.3.1: neighbourhood graph over R = S ∪ U.
  std::vector<bool> periodic;
  for (const auto& v : model.vars) periodic.push_back(v.periodic);
  out.neighbors = neighbor_pairs(out.tree, out.boxes, periodic, model.initial_box());

  // 4.3.2: certified links between solution boxes (P3).
  ModelEvaluator ev(model);
  HsWorkspace ws;
  LinkProof lp;
  for (size_t e = 0; e < out.neighbors.size(); ++e) {
    const auto& pr = out.neighbors[e];
    if (!out.certified[pr.a] || !out.certified[pr.b]) continue;
    if (!certify_link(ev, out.boxes, pr, config.tau, lp, ws)) continue;
    out.certified_links.push_back(int32_t(e));
    if (config.keep_link_proofs) out.link_proofs.push_back(lp);
  }

  // 4.4.1: CSNCs = components of (S, N), largest first; then filtering.
  std::vector<int32_t> vertex(out.boxes.size(), -1), box_of;
  for (int b = 0; b < out.boxes.size(); ++b)
    if (out.certified[b]) {
      vertex[b] = int32_t(box_of.size());
      box_of.push_back(b);
    }
  std::vector<std::pair<int32_t, int32_t>> edges;
  for (int32_t e : out.certified_links)
    edges.emplace_back(vertex[out.neighbors[e].a], vertex[out.neighbors[e].b]);
  Components comps = connected_components(int(box_of.size()), edges);
  out.csnc.assign(out.boxes.size(), -1);
  for (size_t v = 0; v < box_of.size(); ++v) out.csnc[box_of[v]] = comps.of[v];
  out.csnc_sizes = comps.sizes;
  out.filtered = filter_components(out.csnc_sizes);

  // 4.4.2: separation by factor signs; the certified lower bound (11).
  out.separation = separate_by_signs(out.boxes.size(), int(out.factors.size()), out.signs,
                                     out.certified, out.neighbors);
  out.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace aspects
