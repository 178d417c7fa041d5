#include "search_phase.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "checker_gap.h"
#include "contractor.h"
#include "model/constraints.h"
#include "model/model_eval.h"
#include "part_merger.h"
#include "remote_subtrees.h"
#include "search_state.h"
#include "solution_box.h"
#include "subtree_work.h"

namespace aspects {

namespace {

// The parts of the NCSP (4)'s search for one thread: one evaluator shared by Prune, Prove
// and the factor signs.
struct NcspParts {
  ModelEvaluator ev;
  ConstraintChecker constraints;
  EquationContractor equations;
  CheckerGapContractor contractor;
  SolutionBoxProver prover;
  std::unique_ptr<Bisector> bisector;
  FactorSigns signs;

  NcspParts(const Model& m, const AspectsConfig& c, const std::vector<Factor>& factors)
      : ev(m, c.arithmetic), constraints(m, ev), equations(ev), contractor(equations, c.grid_records),
        prover(ev, constraints, c.tau, c.max_newton_iterations, c.grid_records),
        bisector(make_bisector(c.bisector, m, c.eps)), signs(ev, m, factors) {
    bisector->set_split_fraction(c.split_fraction);
    c.made(ev.arithmetic());
  }
  SearchParts parts() { return {contractor, prover, *bisector, constraints, signs}; }
};

// Runs Algorithm 1 on one part of the tree.
bool search_part(const Model& m, const AspectsConfig& c, const std::vector<Factor>& factors,
                 const Box& root, int parent_split, SearchPart& part, TreeSink* sink,
                 SearchStats& stats, const std::function<void()>& tick, int defer_depth,
                 std::vector<DeferredSubtree>* deferred) {
  part.boxes = OutputBoxes(int(m.vars.size()), int(factors.size()));
  part.diagnostics = SearchDiagnostics();
  NcspParts parts(m, c, factors);
  AspectsSearch steps(m.n(), parts.parts(), part.boxes, part.diagnostics, sink);
  bool complete = branch_and_prune(root, steps, part.tree, stats, tick, parent_split,
                                   defer_depth, deferred, c.stop);
  if (sink) sink->finished();
  return complete;
}

// Checkpoints while the subtrees are searched: `done` changes under `state_lock`; the
// callback gets a copy, and reads only finished parts, which no thread changes any more.
// Each write rewrites the whole state, which grows with the run: the next periodic one
// waits at least 19 times as long as the last took, so that writing them holds a thread
// for at most a twentieth of the time (a default interval of a minute must not cost a
// run of hours, whose checkpoint is gigabytes, most of its time).
class Checkpointer {
 public:
  Checkpointer(const AspectsConfig& c, SearchState& st)
      : c_(c), st_(st), wait_(c.checkpoint_seconds) {}
  void mark_done(size_t k) {
    std::lock_guard<std::mutex> g(state_lock_);
    st_.done[k] = 1;
  }
  // Unless forced, only when `checkpoint_seconds` have passed and no other thread writes.
  void write(bool forced) {
    if (!c_.checkpoint) return;
    std::unique_lock<std::mutex> one(write_lock_, std::defer_lock);
    if (forced) one.lock();
    else if (!one.try_lock()) return;
    std::vector<uint8_t> done;
    {
      std::lock_guard<std::mutex> g(state_lock_);
      auto now = std::chrono::steady_clock::now();
      if (!forced && std::chrono::duration<double>(now - last_).count() < wait_) return;
      done = st_.done;
    }
    const auto start = std::chrono::steady_clock::now();
    c_.checkpoint(st_, done);
    std::lock_guard<std::mutex> g(state_lock_);
    last_ = std::chrono::steady_clock::now();
    wait_ = std::max(c_.checkpoint_seconds,
                     kWaitPerWrite * std::chrono::duration<double>(last_ - start).count());
  }

 private:
  const AspectsConfig& c_;
  SearchState& st_;
  std::mutex state_lock_, write_lock_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
  static constexpr double kWaitPerWrite = 19;
  double wait_;  // seconds from the last write to the next periodic one
};

// A resumed state must have been made with this model's factors.
void check_resumed(const SearchState& st, size_t factors) {
  auto fits = [&](const SearchPart& part) { return size_t(part.boxes.factors()) == factors; };
  bool fit = fits(st.top);
  for (size_t k = 0; k < st.deferred.size(); ++k) fit = fit && (!st.done[k] || fits(st.parts[k]));
  if (!fit) throw std::runtime_error("resumed search state does not match the model's factors");
}

// Progress only: the share of the domain a resumed checkpoint had decided.
double resumed_share(const SearchState& st, const SearchStats& stats) {
  double decided = 1;
  for (size_t k = 0; k < st.deferred.size(); ++k)
    if (!st.done[k]) decided -= stats.share(st.deferred[k].box);
  return decided;
}

// Progress only: a part searched elsewhere, counted as if searched here.
void count_for_progress(ReturnedPart& part, const Box& cell, SearchStats& stats) {
  if (part.bytes.empty()) count_leaves(part.part, part);
  stats.processed += part.nodes;
  stats.solutions += part.solutions;
  stats.undecided += part.undecided;
  stats.discarded += part.discarded;
  if (!stats.domain_width.empty()) stats.add_decided(stats.share(cell));
}

// Deferred subtree k searched by this process. Its certificate sink is opened only now: a
// file each, and a deep cut makes more subtrees than a process may hold files open.
// `cert_lock` guards the writer's list of subtrees, which grows as they are taken and which
// a checkpoint reads.
void search_here(int32_t k, const Model& model, const AspectsConfig& config,
                 const std::vector<Factor>& factors, SearchState& st, SearchStats& stats,
                 const std::function<void()>& tick, Checkpointer& checkpoints,
                 std::mutex& cert_lock) {
  TreeSink* sink = nullptr;
  if (config.certificate) {
    std::lock_guard<std::mutex> g(cert_lock);
    sink = config.certificate->subtree(k, st.deferred[k].box);
  }
  PartClock clock;
  if (search_part(model, config, factors, st.deferred[k].box, st.deferred[k].parent_split,
                  st.parts[k], sink, stats, tick, -1, nullptr))
    checkpoints.mark_done(size_t(k));
  if (config.subtree_observer.searched_here)
    config.subtree_observer.searched_here(k, st.parts[k], clock.work());
  if (config.checkpoint_seconds > 0) {
    std::lock_guard<std::mutex> g(cert_lock);
    checkpoints.write(false);
  }
}

// The subtrees shared with other processes (config.remote): this process's threads and the
// remote server take them from one queue.
void search_with_remote(const Model& model, const AspectsConfig& config,
                        const std::vector<Factor>& factors, SearchState& st, SearchStats& stats,
                        const std::function<void()>& tick, Parallel& parallel,
                        Checkpointer& checkpoints) {
  const long prec = working_precision();
  SubtreeQueue queue(st.done);
  CertificateSink* cert = config.certificate;
  std::mutex cert_lock;  // see search_here
  std::exception_ptr remote_error, local_error;
  std::thread server([&] {
    try {
      config.remote->serve(
          queue, st.deferred, int(factors.size()), [&] { return config.search_stopped(); },
          [&](int32_t k, PartOutcome outcome, ReturnedPart&& part, std::string&& records) {
            count_for_progress(part, st.deferred[k].box, stats);
            if (config.subtree_observer.returned)
              config.subtree_observer.returned(k, part, size_t(part.record_bytes));
            st.parts[k] = std::move(part.part);
            st.encoded[k] = {std::move(part.bytes), part.nodes, part.boxes};
            std::lock_guard<std::mutex> g(cert_lock);
            if (cert && part.fetch_records)
              cert->restore_later(k, std::move(part.fetch_records));
            else if (cert)
              cert->restore(k, records);
            if (outcome == PartOutcome::Complete) checkpoints.mark_done(k);
            // Another rank stopped by a signal of its own stops the run: its part is partial.
            else if (config.stop) config.stop->request(StopReason::Signal);
            if (config.checkpoint_seconds > 0) checkpoints.write(false);
          },
          /*records_may_wait=*/!config.checkpoint);
    } catch (...) {
      remote_error = std::current_exception();
    }
  });
  try {
    parallel.arena().execute([&] {
      tbb::parallel_for(0, std::max(1, config.threads), [&](int) {
        set_working_precision(prec);  // MPFR's default precision is per thread
        for (int32_t k; (k = queue.claim()) >= 0;)
          search_here(k, model, config, factors, st, stats, tick, checkpoints, cert_lock);
      }, tbb::simple_partitioner());
    });
  } catch (...) {
    local_error = std::current_exception();  // the server still ends: the others drain the queue
  }
  server.join();
  if (local_error) std::rethrow_exception(local_error);
  if (remote_error) std::rethrow_exception(remote_error);
}

}  // namespace

bool search_subtree(const Model& model, const AspectsConfig& config,
                    const std::vector<Factor>& factors, const DeferredSubtree& subtree,
                    SearchPart& part, TreeSink* sink) {
  SearchStats stats;
  return search_part(model, config, factors, subtree.box, subtree.parent_split, part, sink,
                     stats, {}, -1, nullptr);
}

SearchOutcome search_phase(const Model& model, const AspectsConfig& config,
                           const std::vector<Factor>& factors, Parallel& parallel,
                           PhaseClock& clock) {
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
  if (cert) cert->begin(root, factors);

  SearchState fresh;
  SearchState& st = config.resume ? *config.resume : fresh;
  if (!st.top_done) {
    st = SearchState();
    PartClock top_clock;
    st.top_done = search_part(model, config, factors, root, -1, st.top,
                              cert ? cert->top() : nullptr, stats, tick, config.defer_depth,
                              &st.deferred);
    st.parts.resize(st.deferred.size());
    st.done.assign(st.deferred.size(), 0);
    if (config.subtree_observer.top_searched)
      config.subtree_observer.top_searched(st, top_clock.work());
  }
  check_resumed(st, factors.size());
  st.encoded.resize(st.deferred.size());  // a fresh or resumed state holds decoded parts only
  if (config.resume && st.top_done) stats.resumed_share = resumed_share(st, stats);
  Checkpointer checkpoints(config, st);
  if (config.remote) {
    search_with_remote(model, config, factors, st, stats, tick, parallel, checkpoints);
  } else {
    std::mutex cert_lock;  // see search_here
    parallel.arena().execute([&] {
      tbb::parallel_for(size_t(0), st.deferred.size(), [&](size_t k) {
        if (st.done[k]) return;
        set_working_precision(prec);  // MPFR's default precision is per thread
        search_here(int32_t(k), model, config, factors, st, stats, tick, checkpoints, cert_lock);
      }, tbb::simple_partitioner());
    });
  }
  bool all_done = st.top_done;
  for (uint8_t d : st.done) all_done = all_done && d;
  if (!all_done) checkpoints.write(true);  // stopped: what a resumed run needs
  clock.lap("search");

  SearchOutcome out;
  out.boxes = OutputBoxes(int(model.vars.size()), int(factors.size()));
  // Another process's parts are decoded one at a time as they are grafted: never all of
  // them held twice, encoded and decoded.
  const int p = int(factors.size());
  PartMerger(st.parts, out.boxes, out.tree)
      .merge(st.top, &st.encoded, [&](int32_t k, const std::string& bytes, SearchPart& part) {
        config.remote->decode(k, bytes, p, part);
      });
  out.diagnostics.add(st.top.diagnostics);
  for (const auto& part : st.parts) out.diagnostics.add(part.diagnostics);
  st = SearchState();  // merged: a resumed state is consumed
  clock.lap("merge");
  return out;
}

}  // namespace aspects
