#include "generalized_aspects.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <cmath>
#include <memory>
#include <string>
#include <unordered_map>

#include "assembly_witness.h"
#include "checker_margins.h"
#include "model/constraints.h"
#include "contractor.h"
#include "model/determinant_factors.h"
#include "model/model_eval.h"
#include "search_state.h"
#include "search/stop_condition.h"

namespace aspects {

namespace {

// Algorithm 1's steps for the NCSP (4): f = 0, det Fx ≠ 0, det Fq ≠ 0, assembled from
// the contractor (Prune), the solution-box prover (Prove) and the bisector (Branch).
// This class adds what ties them to this problem: the certificate records, the output
// boxes with their factor signs, the additional constraints and the diagnostics.
class AspectsSearch : public BranchAndPruneSteps {
 public:
  AspectsSearch(const Model& m, const AspectsConfig& cfg, AspectsResult& out, TreeSink* sink)
      : m_(m), out_(out), sink_(sink), ev_(m), constraints_(m, ev_), contractor_(ev_),
        prover_(ev_, constraints_, cfg.tau, cfg.max_newton_iterations),
        bisector_(make_bisector(cfg.bisector, m, cfg.eps)), n_(m.n()),
        nv_(int(m.vars.size())) {
    for (const auto& f : out_.factors) factor_nodes_.push_back(f.node);
    factor_prog_ = m.dag.closure(factor_nodes_);
    for (int i = 0; i < n_; ++i) hints_.push_back("eq" + std::to_string(i));
  }

  // Prune: contraction, recorded for the certificate with a gap, then the constraints.
  bool prune(Box& box, int32_t& reason) override {
    cell_ = box;
    Refutation r = contractor_.contract(box);
    if (r) {
      bool by_equation = r.kind == Refutation::Equation;
      reason = by_equation ? r.equation : n_;
      ++(by_equation ? out_.diagnostics.refuted_by_equation : out_.diagnostics.refuted_by_newton);
      if (sink_) sink_->discard(by_equation ? hints_[r.equation].c_str() : "hs");
      return false;
    }
    // Leave a gap between the contraction and the recorded box, so that the closed
    // slabs a checker refutes (certificates/FORMAT.md) really hold no solution.
    for (int v = 0; v < nv_; ++v) {
      double clo = cell_[v].lo_down(), chi = cell_[v].hi_up();
      double lo = box[v].lo_down(), hi = box[v].hi_up();
      double gap_lo = margins::contraction_gap(chi - clo, lo);
      double gap_hi = margins::contraction_gap(chi - clo, hi);
      lo = lo - gap_lo <= clo ? clo : std::nextafter(lo - gap_lo, -INFINITY);
      hi = hi + gap_hi >= chi ? chi : std::nextafter(hi + gap_hi, INFINITY);
      // Below 53 bits the box's interval rounds these outward to the working precision:
      // record what it holds, so that the record and the search's box are the same.
      box[v].set_hull(lo, hi);
      lo = box[v].lo_down();
      hi = box[v].hi_up();
      if ((lo > clo || hi < chi) && sink_) sink_->contraction(v, lo, hi);
    }
    // Additional constraints (paper 5.4): a box where one certainly fails holds no
    // feasible configuration.
    int violated = -1;
    pruned_truth_ = constraints_.evaluate(box, &violated);
    if (pruned_truth_ == Truth::False) {
      if (sink_) sink_->discard(("c" + std::to_string(violated)).c_str());
      reason = n_ + 1 + violated;
      ++out_.diagnostics.refuted_by_constraint;
      return false;
    }
    return true;
  }

  void branched(int var, double at) override {
    if (sink_) sink_->split(var, at);
  }

  void deferred(int32_t task) override {
    if (sink_) sink_->deferred(task);
  }

  Verdict prove(const Box& cell, int32_t& index) override {
    Verdict v = prover_.prove(cell, reported_, proof_);
    ++out_.diagnostics.attempts[int(v)];
    if (v != Verdict::Solution) return v;
    index = store(reported_, true);
    if (sink_) sink_->solution(index, last_signs(), proof_);
    return v;
  }

  int32_t keep_undecided(const Box& box, Verdict why) override {
    int32_t index = store(box, false);
    ++out_.diagnostics.undecided[int(why)];
    // `box` is the box prune() just returned: its constraint truth is known.
    bool on_constraint = pruned_truth_ == Truth::Unknown || why == Verdict::ConstraintBoundary;
    bool p2 = why == Verdict::SingularFx || why == Verdict::SingularFq;
    out_.undecided_kind[index] = on_constraint ? UndecidedKind::Constraint
                                 : p2          ? UndecidedKind::Singular
                                               : UndecidedKind::NoExistence;
    if (sink_) sink_->undecided(index, last_signs());
    return index;
  }

  int32_t keep_unexplored(const Box& cell) override {
    int32_t index = store(cell, false);
    out_.undecided_kind[index] = UndecidedKind::Unexplored;
    if (sink_) sink_->unexplored(index, last_signs());
    return index;
  }

  SplitChoice choose_split(const Box& box, const SplitContext& ctx) override {
    return bisector_->choose(box, ctx);
  }

 private:
  // A sign is claimed only when the enclosure clears 0 by a margin, so that another
  // sound enclosure (the checker's) can confirm it.
  static int sign_with_margin(const Interval& d) {
    double lo = d.lo_down(), hi = d.hi_up();
    double margin = margins::sign_clearance() * (hi - lo) + margins::sign_clearance_abs;
    if (lo > margin) return 1;
    if (hi < -margin) return -1;
    return 0;
  }

  const int8_t* last_signs() const {
    return out_.signs.data() + out_.signs.size() - out_.factors.size();
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
  AspectsResult& out_;
  TreeSink* sink_;
  ModelEvaluator ev_;
  ConstraintChecker constraints_;
  EquationContractor contractor_;
  SolutionBoxProver prover_;
  std::unique_ptr<Bisector> bisector_;
  int n_, nv_;
  std::vector<int> factor_nodes_, factor_prog_;
  Box reported_, cell_;
  std::vector<std::string> hints_;
  SolutionProof proof_;
  Truth pruned_truth_ = Truth::True;  // of the last box prune() kept
};

}  // namespace

namespace {

// Rebuilds one tree from the top part and the subtrees, depth first, and numbers the
// output boxes in that order (the order of the certificate's records).
class PartMerger {
 public:
  PartMerger(std::vector<SearchPart>& parts, AspectsResult& out)
      : parts_(parts), out_(out), p_(out.factors.size()) {}

  // Room for everything first, and each part's arrays freed once grafted: the merge used
  // to hold the search's tree and boxes twice, and more while vectors grew.
  void merge(SearchPart& top) {
    size_t nodes = top.tree.size(), boxes = top.out.boxes.size();
    for (const SearchPart& part : parts_) {
      nodes += part.tree.size();
      boxes += part.out.boxes.size();
    }
    out_.tree.reserve(nodes);
    out_.boxes.reserve(boxes);
    out_.certified.reserve(boxes);
    out_.undecided_kind.reserve(boxes);
    out_.signs.reserve(boxes * p_);
    out_.tree.emplace_back();
    graft(top, 0, 0);
    release(top);
  }

 private:
  // Node i of `part` and the tree below it into out_.tree[id]; the children of an internal
  // node take two adjacent new slots, as in the search.
  void graft(SearchPart& part, int32_t i, int32_t id) {
    const SearchNode src = part.tree[i];
    if (src.fate == LeafFate::Deferred && !src.internal()) {
      SearchPart& sub = parts_[src.index];
      graft(sub, 0, id);
      release(sub);  // each part is grafted once, whole
      return;
    }
    out_.tree[id] = src;
    if (src.internal()) {
      const int32_t first = int32_t(out_.tree.size());
      out_.tree.emplace_back();
      out_.tree.emplace_back();
      out_.tree[id].index = first;
      graft(part, src.left(), first);
      graft(part, src.right(), first + 1);
    } else if (src.index >= 0) {
      if (src.index != part.next_leaf++) throw std::logic_error("merge: leaves out of order");
      out_.tree[id].index = take_box(part.out, src.index);
    }
  }

  int32_t take_box(const AspectsResult& from, int32_t b) {
    int32_t id = out_.boxes.push_copy(from.boxes, b);
    out_.certified.push_back(from.certified[b]);
    out_.undecided_kind.push_back(from.undecided_kind[b]);
    for (size_t i = 0; i < p_; ++i) out_.signs.push_back(from.signs[b * p_ + i]);
    return id;
  }

  // The merged arrays of a part; its diagnostics stay.
  static void release(SearchPart& part) {
    std::vector<SearchNode>().swap(part.tree);
    part.out.boxes.release();
    std::vector<uint8_t>().swap(part.out.certified);
    std::vector<UndecidedKind>().swap(part.out.undecided_kind);
    std::vector<int8_t>().swap(part.out.signs);
  }

  std::vector<SearchPart>& parts_;
  AspectsResult& out_;
  size_t p_;
};

}  // namespace

void SearchDiagnostics::add(const SearchDiagnostics& o) {
  for (int k = 0; k < kVerdicts; ++k) {
    attempts[k] += o.attempts[k];
    undecided[k] += o.undecided[k];
  }
  refuted_by_equation += o.refuted_by_equation;
  refuted_by_newton += o.refuted_by_newton;
  refuted_by_constraint += o.refuted_by_constraint;
}

AspectsResult compute_aspects(Model& model, const AspectsConfig& config) {
  auto t0 = std::chrono::steady_clock::now();
  AspectsResult out;
  out.factors = determinant_factors(model);  // adds nodes: before any evaluator exists
  const int nv = int(model.vars.size());
  out.boxes = BoxStore(nv);
  out.link_proofs = LinkRecords(model.n());
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
  for (const auto& x : root) stats.domain_width.push_back(x.hi_up() - x.lo_down());
  CertificateSink* cert = config.certificate;
  if (cert) cert->begin(root, out.factors);

  // The top of the tree, then the subtrees below `defer_depth`, in parallel. The
  // result does not depend on the number of threads: the subtrees are fixed, and are
  // merged back in depth-first order. Parts already in a resumed state are not searched.
  auto new_part = [&](SearchPart& part) {
    part.out.factors = out.factors;
    part.out.boxes = BoxStore(nv);
  };
  SearchState fresh;
  SearchState& st = config.resume ? *config.resume : fresh;
  if (!st.top_done) {
    st = SearchState();
    new_part(st.top);
    TreeSink* sink = cert ? cert->top() : nullptr;
    AspectsSearch search(model, config, st.top.out, sink);
    st.top_done = branch_and_prune(root, search, st.top.tree, stats, tick, -1,
                                   config.defer_depth, &st.deferred, config.stop);
    if (sink) sink->finished();
    st.parts.resize(st.deferred.size());
    st.done.assign(st.deferred.size(), 0);
  }
  auto fits = [&](SearchPart& part) {  // a resumed part must fit this model
    part.out.factors = out.factors;       // (not saved in checkpoints)
    return part.out.signs.size() == size_t(part.out.boxes.size()) * out.factors.size();
  };
  bool fit = fits(st.top);
  for (size_t k = 0; k < st.deferred.size(); ++k) fit = fit && (!st.done[k] || fits(st.parts[k]));
  if (!fit) throw std::runtime_error("resumed search state does not match the model's factors");
  if (config.resume && st.top_done) {  // progress: what the checkpoint had decided
    double decided = 1;
    for (size_t k = 0; k < st.deferred.size(); ++k)
      if (!st.done[k]) decided -= stats.share(st.deferred[k].box);
    stats.resumed_share = decided;
  }
  std::vector<TreeSink*> sinks(st.deferred.size(), nullptr);
  for (size_t k = 0; k < st.deferred.size(); ++k) {
    if (st.done[k]) continue;
    new_part(st.parts[k]);
    if (cert) sinks[k] = cert->subtree(int32_t(k));
  }
  // Checkpoints: `done` changes under `state_lock`; the callback gets a copy, and reads
  // only finished parts, which no thread changes any more.
  std::mutex state_lock, checkpoint_lock;
  auto last_checkpoint = std::chrono::steady_clock::now();
  auto checkpoint = [&](bool forced) {
    if (!config.checkpoint) return;
    std::unique_lock<std::mutex> one(checkpoint_lock, std::defer_lock);
    if (forced) one.lock();
    else if (!one.try_lock()) return;
    std::vector<uint8_t> done;
    {
      std::lock_guard<std::mutex> g(state_lock);
      auto now = std::chrono::steady_clock::now();
      if (!forced && std::chrono::duration<double>(now - last_checkpoint).count() <
                         config.checkpoint_seconds)
        return;
      done = st.done;
    }
    config.checkpoint(st, done);
    std::lock_guard<std::mutex> g(state_lock);
    last_checkpoint = std::chrono::steady_clock::now();
  };
  tbb::task_arena arena(std::max(1, config.threads));
  arena.execute([&] {
    tbb::parallel_for(size_t(0), st.deferred.size(), [&](size_t k) {
      if (st.done[k]) return;
      set_working_precision(prec);  // MPFR's default precision is per thread
      AspectsSearch search(model, config, st.parts[k].out, sinks[k]);
      bool complete = branch_and_prune(st.deferred[k].box, search, st.parts[k].tree, stats, tick,
                                       st.deferred[k].parent_split, -1, nullptr, config.stop);
      if (sinks[k]) sinks[k]->finished();
      if (complete) {
        std::lock_guard<std::mutex> g(state_lock);
        st.done[k] = 1;
      }
      if (config.checkpoint_seconds > 0) checkpoint(false);
    }, tbb::simple_partitioner());
  });
  bool all_done = st.top_done;
  for (uint8_t d : st.done) all_done = all_done && d;
  if (!all_done) checkpoint(true);  // stopped: what a resumed run needs
  auto lap = [&, last = t0](const char* phase) mutable {
    auto now = std::chrono::steady_clock::now();
    out.phase_seconds.emplace_back(phase, std::chrono::duration<double>(now - last).count());
    out.phase_peak_mib.emplace_back(phase, peak_resident_bytes() / (1024.0 * 1024.0));
    last = now;
  };
  lap("search");
  for (auto& part : st.parts) part.next_leaf = 0;
  PartMerger(st.parts, out).merge(st.top);
  out.diagnostics.add(st.top.out.diagnostics);
  for (const auto& part : st.parts) out.diagnostics.add(part.out.diagnostics);
  st = SearchState();  // merged into `out`: a resumed state is consumed
  lap("merge");
  // Counted on the merged tree, not by `stats`: a resumed run did not process every node.
  for (const SearchNode& node : out.tree) {
    if (node.internal()) {
      ++out.processed;
      continue;
    }
    out.processed += node.fate != LeafFate::Unexplored;
    out.solutions += node.fate == LeafFate::Solution;
    out.undecided += node.fate == LeafFate::Undecided;
    out.discarded += node.fate == LeafFate::Discarded;
    out.unexplored += node.fate == LeafFate::Unexplored;
  }
  if (out.unexplored > 0) out.stopped_by = config.stop->reason();

  // 4.3.1: neighbourhood graph over R = S ∪ U.
  std::vector<bool> periodic;
  for (const auto& v : model.vars) periodic.push_back(v.periodic);
  const ForEachIndex in_arena = [&](int n, const std::function<void(int32_t)>& body) {
    arena.execute([&] {
      // One index per task: the callers' indices are blocks of boxes or CSNCs (a few
      // large CSNCs hold nearly all the witness work).
      tbb::parallel_for(
          tbb::blocked_range<int>(0, n, 1),
          [&](const tbb::blocked_range<int>& r) {
            for (int i = r.begin(); i < r.end(); ++i) body(i);
          },
          tbb::simple_partitioner());
    });
  };
  // 4.3.2: certified links between solution boxes (P3), in blocks processed in
  // parallel and concatenated in order. Unless all links are asked for, a link is proved
  // only when it joins two components: rounds of blocks read the components known at the
  // round's start (and their own links), then join theirs in order, so that the links
  // proved do not depend on the number of threads.
  const size_t block = 4096, round_pairs = 8 * block;
  // The components joined so far (Boost's disjoint sets over the boxes), changed only
  // between rounds; during a round the blocks read `parent` without path compression.
  const int joinable = config.all_links ? 0 : out.boxes.size();
  // Ranks stay below log2 of the box count: a byte each.
  std::vector<uint8_t> rank(joinable);
  std::vector<int> parent(joinable);
  boost::disjoint_sets<uint8_t*, int*> joined(rank.data(), parent.data());
  for (int b = 0; b < joinable; ++b) joined.make_set(b);
  auto joined_root = [&](int32_t x) {
    while (parent[x] != x) x = parent[x];
    return x;
  };
  // M's pairs between solution boxes, in M's order, from `first` on not yet tried.
  std::vector<NeighborPair> candidates;
  size_t first = 0;
  // One round: the links among candidates[first, first + count), which are then done.
  auto link_round = [&](size_t count) {
    const size_t blocks = (count + block - 1) / block;
    std::vector<std::vector<int32_t>> block_links(blocks);
    std::vector<LinkRecords> block_proofs(blocks, LinkRecords(model.n()));
    arena.execute([&] {
      tbb::parallel_for(size_t(0), blocks, [&](size_t k) {
        set_working_precision(prec);
        ModelEvaluator ev(model);
        HsWorkspace ws;
        LinkProof lp;
        std::unordered_map<int32_t, int32_t> local;  // joins made by this block so far
        auto local_root = [&](int32_t x) {
          int32_t r = x;
          for (auto it = local.find(r); it != local.end(); it = local.find(r)) r = it->second;
          // Path compression: without it the chains grow with the block's links, and on
          // 3-RPR at eps 0.3 these lookups took half of the link phase.
          for (auto it = local.find(x); it != local.end() && it->second != r; it = local.find(x)) {
            x = it->second;
            it->second = r;
          }
          return r;
        };
        const size_t end = first + std::min(count, (k + 1) * block);
        for (size_t e = first + k * block; e < end; ++e) {
          const auto& pr = candidates[e];
          int32_t ra = 0, rb = 0;
          if (!config.all_links) {
            ra = local_root(joined_root(pr.a));
            rb = local_root(joined_root(pr.b));
            if (ra == rb) continue;
          }
          if (!certify_link(ev, out.boxes, pr, config.tau, lp, ws)) continue;
          if (!config.all_links) local[ra] = rb;
          block_links[k].push_back(int32_t(e));
          if (config.keep_link_proofs) block_proofs[k].push(lp);
        }
      });
    });
    // In order; a link joining what another block of the round already joined is dropped.
    for (size_t k = 0; k < blocks; ++k) {
      for (size_t i = 0; i < block_links[k].size(); ++i) {
        const NeighborPair& pr = candidates[block_links[k][i]];
        if (!config.all_links) {
          int ra = joined.find_set(pr.a), rb = joined.find_set(pr.b);
          if (ra == rb) continue;
          joined.link(ra, rb);
        }
        out.certified_links.push_back(int32_t(out.neighbors.size()));
        out.neighbors.push_back(pr);
        if (config.keep_link_proofs) out.link_proofs.append_one(block_proofs[k], i);
      }
    }
    first += count;
  };
  // 4.4.2: forests for as many sign classes as fit in 1 GiB; any others (a model with many
  // factors that may vanish together) take passes over M of their own, below.
  const int p = int(out.factors.size());
  const std::vector<uint32_t> classes =
      SignSeparation::counting_classes(out.boxes.size(), p, out.signs, out.certified);
  const size_t per_pass =
      std::max<size_t>(1, (size_t(1) << 30) / (5 * size_t(std::max(1, out.boxes.size()))));
  auto pass_classes = [&](size_t first_class) {
    const size_t last_class = std::min(classes.size(), first_class + per_pass);
    return std::vector<uint32_t>(classes.begin() + first_class, classes.begin() + last_class);
  };
  SignSeparation separation(out.boxes.size(), p, out.signs, pass_classes(0));
  // M streams through the separation's union–find and, its pairs between solution boxes,
  // through the rounds of links: neither M nor those pairs (150 M, 1.8 GB, on 3-RPR at
  // eps 0.3) are ever held whole. The rounds are those of the whole list.
  stream_neighbor_pairs(
      out.tree, out.boxes, periodic,
      [&](const std::vector<NeighborPair>& piece) {
        out.neighbor_count += piece.size();
        separation.add(piece, in_arena);
        for (const NeighborPair& pr : piece)
          if (out.certified[pr.a] && out.certified[pr.b]) candidates.push_back(pr);
        while (candidates.size() - first >= round_pairs) link_round(round_pairs);
        candidates.erase(candidates.begin(), candidates.begin() + first);
        first = 0;
      },
      in_arena);
  link_round(candidates.size() - first);
  std::vector<NeighborPair>().swap(candidates);

  lap("neighbourhood graph, separation and links");
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
  out.separation = separation.result(out.certified, &out.csnc);
  for (size_t c = per_pass; c < classes.size(); c += per_pass) {
    SignSeparation more(out.boxes.size(), p, out.signs, pass_classes(c));
    stream_neighbor_pairs(
        out.tree, out.boxes, periodic,
        [&](const std::vector<NeighborPair>& piece) { more.add(piece, in_arena); }, in_arena);
    merge_separation(out.separation, more.result(out.certified, &out.csnc));
  }
  lap("components and separation");
  // Paper 3.2: "one pose, two commands" witnesses of cuspidality inside each CSNC. The
  // CSNCs are searched in parallel; the witnesses are the same for any thread count.
  const WitnessSpace space(model.pose, model.command, periodic);
  const int csncs = int(out.csnc_sizes.size());
  out.cuspidal = find_pose_witnesses(out.boxes, out.csnc, csncs, space, 10000, in_arena);
  lap("cuspidality");
  // ... and "one command, two poses" (assembly-mode changes), each proved in x at a point.
  struct AssemblyProver {
    ModelEvaluator ev;
    HsWorkspace ws;
    explicit AssemblyProver(const Model& m) : ev(m) {}
  };
  tbb::enumerable_thread_specific<AssemblyProver> provers([&] { return AssemblyProver(model); });
  auto prove = [&](CommandWitness& w) {
    AssemblyProver& p = provers.local();
    return prove_command_witness(p.ev, out.boxes, config.tau, w, p.ws);
  };
  find_command_witnesses(out.boxes, out.csnc, csncs, space, prove, out.cuspidal, 1000, 100000, 2,
                         in_arena);
  lap("assembly witnesses");
  out.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace aspects
