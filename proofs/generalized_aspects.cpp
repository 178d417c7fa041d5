#include "generalized_aspects.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <stdexcept>
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
  AspectsSearch(const Model& m, const AspectsConfig& cfg, AspectsResult& out, TreeSink* sink)
      : m_(m), cfg_(cfg), out_(out), sink_(sink), ev_(m), constraints_(m, ev_), n_(m.n()),
        nv_(int(m.vars.size())) {
    for (const auto& f : out_.factors) factor_nodes_.push_back(f.node);
    factor_prog_ = m.dag.closure(factor_nodes_);
    for (int i = 0; i < n_; ++i) hints_.push_back("eq" + std::to_string(i));
  }

  // Prune: contraction (below), recorded for the certificate.
  bool prune(Box& box, int32_t& reason) override {
    cell_ = box;
    if (!contract(box, reason)) {
      if (sink_)
        sink_->discard(reason < n_ ? hints_[reason].c_str() : "hs");
      return false;
    }
    // Leave a gap between the contraction and the recorded box, so that the closed
    // slabs a checker refutes (certificates/FORMAT.md) really hold no solution.
    for (int v = 0; v < nv_; ++v) {
      double clo = cell_[v].lo_down(), chi = cell_[v].hi_up();
      double lo = box[v].lo_down(), hi = box[v].hi_up();
      // Relative to the cell and to the magnitude of the bound: where the contraction
      // is tight to rounding level (a solution within ulps of it), a gap of a few ulps
      // would leave slabs no independent evaluation can refute.
      double gap = 1e-9 * (chi - clo) + std::ldexp(1.0, -40) * std::max(1.0, std::fabs(lo));
      double gap_hi = 1e-9 * (chi - clo) + std::ldexp(1.0, -40) * std::max(1.0, std::fabs(hi));
      lo = lo - gap <= clo ? clo : std::nextafter(lo - gap, -INFINITY);
      hi = hi + gap_hi >= chi ? chi : std::nextafter(hi + gap_hi, INFINITY);
      box[v].set_hull(lo, hi);
      if ((lo > clo || hi < chi) && sink_) sink_->contraction(v, lo, hi);
    }
    // Additional constraints (paper 5.4): a box where one certainly fails holds no
    // feasible configuration.
    int violated = -1;
    pruned_truth_ = constraints_.evaluate(box, &violated);
    if (pruned_truth_ == Truth::False) {
      if (sink_) sink_->discard(("c" + std::to_string(violated)).c_str());
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
    if (sink_) sink_->split(var, at);
  }

  void deferred(int32_t task) override {
    if (sink_) sink_->deferred(task);
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
      const Variable& var = m_.vars[m_.command[j]];
      // Domain: a command outside its range is not a configuration of the robot. A
      // periodic command may cross its seam: f is 2π-periodic in it (checked by the
      // parser), and the box then stands for its values modulo 2π. The inner enclosure
      // of the bounds, as the checker demands (certificates/FORMAT.md).
      if (var.periodic) continue;
      if (ex.image[j].lo_down() < var.inner_lo || ex.image[j].hi_up() > var.inner_hi)
        return false;
    }
    // A box whose pose misses the declared domain holds no configuration of the robot:
    // it may not count for the bound (possible only within rounding of the root cell).
    for (int v : m_.pose) {
      const Variable& var = m_.vars[v];
      if (var.periodic) continue;
      if (cell[v].hi_up() < var.inner_lo || cell[v].lo_down() > var.inner_hi) return false;
    }
    // The reported commands: the image widened by a small margin (still inside [q̃] and
    // the domain), so that a checker whose enclosure of the image differs in the last
    // bits (another evaluation order, a perturbed preconditioner) still finds it inside.
    reported_ = cell;
    for (int j = 0; j < n_; ++j) {
      int v = m_.command[j];
      const Interval& q = ex.inflated[j];
      double margin = 1e-7 * (q.hi_up() - q.lo_down());
      double lo = std::max(q.lo_down(), ex.image[j].lo_down() - margin);
      double hi = std::min(q.hi_up(), ex.image[j].hi_up() + margin);
      if (!m_.vars[v].periodic) {
        lo = std::max(lo, m_.vars[v].inner_lo);
        hi = std::min(hi, m_.vars[v].inner_hi);
      }
      ex.image[j].set_hull(lo, hi);
      round_out_to_doubles(ex.image[j]);
      reported_[v] = ex.image[j];
    }
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
    if (sink_) sink_->solution(index, last_signs(), proof_);
    return true;
  }

  int32_t keep_undecided(const Box& box) override {
    int32_t index = store(box, false);
    // `box` is the box prune() just returned: its constraint truth is known.
    bool on_constraint = pruned_truth_ == Truth::Unknown;
    out_.undecided_kind[index] = on_constraint ? UndecidedKind::Constraint : last_kind_;
    if (sink_) sink_->undecided(index, last_signs());
    return index;
  }

  // Branch: round robin over the variables wider than eps.
  int choose_split(const Box& box, int parent_split) override {
    if (cfg_.bisection == Bisection::PoseFirst) {
      // The widest pose variable wider than eps; the commands only once every pose
      // variable is narrow (Prune's Hansen–Sengupta step usually locates q before).
      int best = -1;
      for (int group = 0; group < 2 && best < 0; ++group) {
        double widest = cfg_.eps;
        for (int v : group == 0 ? m_.pose : m_.command)
          if (box[v].width_up() > widest) widest = box[v].width_up(), best = v;
      }
      return best;
    }
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

  // A sign is claimed only when the enclosure clears 0 by a margin, so that another
  // sound enclosure (the checker's) can confirm it.
  static int sign_with_margin(const Interval& d) {
    double lo = d.lo_down(), hi = d.hi_up();
    double margin = 1e-9 * (hi - lo) + 1e-300;
    if (lo > margin) return 1;
    if (hi < -margin) return -1;
    return 0;
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
      out_.signs.push_back(s == EvalStatus::Defined ? int8_t(sign_with_margin(ev_.value(f))) : 0);
    return index;
  }

  const Model& m_;
  const AspectsConfig& cfg_;
  AspectsResult& out_;
  TreeSink* sink_;
  ModelEvaluator ev_;
  ConstraintChecker constraints_;
  int n_, nv_;
  std::vector<int> factor_nodes_, factor_prog_;
  Box reported_, retry_, cell_;
  std::vector<std::string> hints_;
  HsWorkspace ws_;
  std::vector<Interval> image_;
  IMatrix J_;
  SolutionProof proof_;
  UndecidedKind last_kind_ = UndecidedKind::NoExistence;
  Truth pruned_truth_ = Truth::True;  // of the last box prune() kept
};

}  // namespace

namespace {

// Output boxes and tree of one part of the search (the top of the tree, or a subtree).
struct SearchPart {
  AspectsResult out;
  std::vector<SearchNode> tree;
  int32_t next_leaf = 0;  // merge cursor: leaves are taken in their local order
};

// Rebuilds one tree from the top part and the subtrees, in depth-first preorder, and
// numbers the output boxes in that order (the order of the certificate's records).
class PartMerger {
 public:
  PartMerger(std::vector<SearchPart>& parts, AspectsResult& out)
      : parts_(parts), out_(out), p_(out.factors.size()) {}

  int32_t graft(SearchPart& part, int32_t i) {
    const SearchNode src = part.tree[i];
    if (src.fate == LeafFate::Deferred && src.split_var < 0)
      return graft(parts_[src.leaf], 0);
    int32_t id = int32_t(out_.tree.size());
    out_.tree.push_back(src);
    if (src.split_var >= 0) {
      int32_t l = graft(part, src.left);
      int32_t r = graft(part, src.right);
      out_.tree[id].left = l;
      out_.tree[id].right = r;
    } else if (src.leaf >= 0) {
      if (src.leaf != part.next_leaf++) throw std::logic_error("merge: leaves out of order");
      out_.tree[id].leaf = take_box(part.out, src.leaf);
    }
    return id;
  }

 private:
  int32_t take_box(const AspectsResult& from, int32_t b) {
    Box box;
    from.boxes.get(b, box);
    int32_t id = out_.boxes.push(box);
    out_.certified.push_back(from.certified[b]);
    out_.undecided_kind.push_back(from.undecided_kind[b]);
    for (size_t i = 0; i < p_; ++i) out_.signs.push_back(from.signs[b * p_ + i]);
    return id;
  }

  std::vector<SearchPart>& parts_;
  AspectsResult& out_;
  size_t p_;
};

}  // namespace

AspectsResult compute_aspects(Model& model, const AspectsConfig& config) {
  auto t0 = std::chrono::steady_clock::now();
  AspectsResult out;
  out.factors = determinant_factors(model);  // adds nodes: before any evaluator exists
  const int nv = int(model.vars.size());
  out.boxes = BoxStore(nv);
  const long prec = working_precision();

  SearchStats stats;
  std::mutex progress_lock;
  std::function<void()> tick;
  if (config.progress)
    tick = [&]() {
      if (!progress_lock.try_lock()) return;
      config.progress(stats);
      progress_lock.unlock();
    };
  Box root = model.initial_box();
  for (auto& x : root) round_out_to_doubles(x);
  CertificateSink* cert = config.certificate;
  if (cert) cert->begin(root, out.factors);

  // The top of the tree, then the subtrees below `defer_depth`, in parallel. The
  // result does not depend on the number of threads: the subtrees are fixed, and are
  // merged back in depth-first order.
  auto new_part = [&](SearchPart& part) {
    part.out.factors = out.factors;
    part.out.boxes = BoxStore(nv);
  };
  SearchPart top;
  new_part(top);
  std::vector<DeferredSubtree> deferred;
  {
    AspectsSearch search(model, config, top.out, cert ? cert->top() : nullptr);
    branch_and_prune(root, search, top.tree, stats, tick, -1, config.defer_depth, &deferred);
  }
  std::vector<SearchPart> parts(deferred.size());
  std::vector<TreeSink*> sinks(deferred.size(), nullptr);
  for (size_t k = 0; k < deferred.size(); ++k) {
    new_part(parts[k]);
    if (cert) sinks[k] = cert->subtree(int32_t(k));
  }
  tbb::task_arena arena(std::max(1, config.threads));
  arena.execute([&] {
    tbb::parallel_for(size_t(0), deferred.size(), [&](size_t k) {
      set_working_precision(prec);  // MPFR's default precision is per thread
      AspectsSearch search(model, config, parts[k].out, sinks[k]);
      branch_and_prune(deferred[k].box, search, parts[k].tree, stats, tick,
                       deferred[k].parent_split);
      if (sinks[k]) sinks[k]->finished();
      deferred[k].box.clear();
    }, tbb::simple_partitioner());
  });
  PartMerger(parts, out).graft(top, 0);
  parts.clear();
  auto lap = [&, last = t0](const char* phase) mutable {
    auto now = std::chrono::steady_clock::now();
    out.phase_seconds.emplace_back(phase, std::chrono::duration<double>(now - last).count());
    last = now;
  };
  lap("search");
  out.processed = stats.processed;
  out.solutions = stats.solutions;
  out.undecided = stats.undecided;
  out.discarded = stats.discarded;

  // 4.3.1: neighbourhood graph over R = S ∪ U.
  std::vector<bool> periodic;
  for (const auto& v : model.vars) periodic.push_back(v.periodic);
  out.neighbors = neighbor_pairs(out.tree, out.boxes, periodic);

  lap("neighbourhood graph");
  // 4.3.2: certified links between solution boxes (P3), in blocks processed in
  // parallel and concatenated in order.
  const size_t block = 4096, blocks = (out.neighbors.size() + block - 1) / block;
  std::vector<std::vector<int32_t>> block_links(blocks);
  std::vector<std::vector<LinkProof>> block_proofs(blocks);
  arena.execute([&] {
    tbb::parallel_for(size_t(0), blocks, [&](size_t k) {
      set_working_precision(prec);
      ModelEvaluator ev(model);
      HsWorkspace ws;
      LinkProof lp;
      size_t end = std::min(out.neighbors.size(), (k + 1) * block);
      for (size_t e = k * block; e < end; ++e) {
        const auto& pr = out.neighbors[e];
        if (!out.certified[pr.a] || !out.certified[pr.b]) continue;
        if (!certify_link(ev, out.boxes, pr, config.tau, lp, ws)) continue;
        block_links[k].push_back(int32_t(e));
        if (config.keep_link_proofs) block_proofs[k].push_back(lp);
      }
    });
  });
  for (size_t k = 0; k < blocks; ++k) {
    out.certified_links.insert(out.certified_links.end(), block_links[k].begin(),
                               block_links[k].end());
    for (auto& lp : block_proofs[k]) out.link_proofs.push_back(std::move(lp));
  }

  lap("certified links");
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
                                     out.certified, out.neighbors, &out.csnc);
  lap("components and separation");
  out.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace aspects
