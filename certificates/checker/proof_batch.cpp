// proof_batch.cpp — speed layer: the interval proofs of a check on T threads (and on the P
// processes of `mpirun -n P check_cert`, ranks.cpp, each with its share of every batch). The record
// rules (check.cpp) read every record and decide its structure themselves, in order; each
// interval proof (a refutation, a Hansen–Sengupta step, a regularity test, a factor sign)
// becomes a job of a batch. A batch runs on every thread, each with its own evaluator and
// prover, and is then judged in record order, so the verdict, the record it names and its
// reason are those of one thread, whatever T and P are: the first failed proof in record order
// wins, and the work limit is charged job by job in record order as a sequential check
// charges it.
#include <flint/flint.h>

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <memory>
#include <new>

#include "speed.h"

namespace cc {

namespace {
constexpr size_t kRun = 32;  // consecutive jobs a worker takes at a time

// Jobs per batch and rank: enough to share, few enough to hold. CHECK_CERT_BATCH changes
// it (the tests use tiny batches, so that many boundaries fall between a proof and its
// record's structural checks); it changes how the work is shared, never the verdict.
size_t batch_size() {
  const char* e = std::getenv("CHECK_CERT_BATCH");
  const long v = e ? std::atol(e) : 0;
  return (v >= 1 && v <= (1 << 20) ? size_t(v) : 4096) * size_t(ranks::size());
}
}  // namespace

struct ProofBatch::Worker {
  std::unique_ptr<Evaluator> ev;
  std::unique_ptr<Prover> pr;
};

// How a proof ended: a value, so that another rank can be told it.
enum class Ended : uint64_t { Held, Failed, OverWork, OutOfMemory, Threw };

struct ProofBatch::Job {
  long record;
  uint64_t limit;  // the work a sequential check may have done by the end of this job
  Proof proof;
  Ended ended = Ended::Held;
  std::string why;    // Failed: the rejection reason; Threw: what was thrown
  uint64_t work = 0;  // node evaluations it took
};

ProofBatch::ProofBatch(const Model& m, int threads, uint64_t work_before)
    : work(work_before), prec_(mpfr_get_default_prec()), batch_(batch_size()) {
  for (int t = 0; t < std::max(1, threads); ++t) {
    workers_.emplace_back(new Worker);
    workers_.back()->ev.reset(new Evaluator(m));
    workers_.back()->pr.reset(new Prover(*workers_.back()->ev));
  }
}

// The helpers finish the jobs they hold (which read the checker's members) before any of
// it is gone, whatever was thrown.
ProofBatch::~ProofBatch() {
  for (std::thread& h : helpers_) h.join();
}

// Queues a job; a full batch starts on the helpers once the one before it is judged, and
// the reader goes on filling the next one meanwhile.
void ProofBatch::add(long record, uint64_t limit, Proof proof) {
  if (failed_) return;
  jobs_.push_back(Job{record, limit, std::move(proof), Ended::Held, {}, 0});
  if (jobs_.size() < batch_) return;
  finish();
  start();
}

// This rank's jobs of the running batch, a run of consecutive ones at a time (neighbouring
// records share boxes, which the evaluator's caches keep; run c is rank c mod P's), on
// worker t, until none is left.
void ProofBatch::work_on(int t) {
  Worker& w = *workers_[t];
  const size_t N = running_.size(), P = size_t(ranks::size());
  for (size_t i; (i = (next_.fetch_add(1) * P + size_t(ranks::rank())) * kRun) < N;)
    for (size_t k = i; k < std::min(N, i + kRun); ++k) {
      Job& j = running_[k];
      // Stopped where a sequential check, having done `work` before this batch, would be
      // stopped at the latest; the judgement charges the jobs before it too.
      w.ev->work = 0;
      w.ev->work_limit = j.limit > work ? j.limit - work : 0;
      try {
        j.why = j.proof(*w.pr);
        j.ended = j.why.empty() ? Ended::Held : Ended::Failed;
      } catch (const WorkLimit&) {
        j.ended = Ended::OverWork;
      } catch (const std::bad_alloc&) {
        j.ended = Ended::OutOfMemory;
      } catch (const std::exception& e) {
        j.ended = Ended::Threw;
        j.why = e.what();
      }
      j.work = w.ev->work;
      j.proof = nullptr;  // the captured boxes are no longer needed
    }
}

// The queued jobs become the running batch, on a helper thread per worker but the first
// (finish() runs it on this thread too). The helpers take the certificate's precision as
// their default for the temporaries they make (MPFR keeps it per thread).
void ProofBatch::start() {
  running_.swap(jobs_);
  next_ = 0;
  for (int t = 1; t < int(workers_.size()) && !running_.empty(); ++t)
    helpers_.emplace_back([this, t] {
      mpfr_set_default_prec(prec_);
      work_on(t);
      mpfr_free_cache();  // this thread's constants (π) are its own,
      flint_cleanup();    // and so are Arb's
    });
}

// Completes the running batch (this thread helps), then judges it in record order.
void ProofBatch::finish() {
  if (running_.empty()) return;
  work_on(0);
  for (std::thread& h : helpers_) h.join();
  helpers_.clear();
  std::vector<Job> jobs;
  jobs.swap(running_);
  share(jobs);
  for (size_t k = 0; k < jobs.size(); ++k) {
    Job& j = jobs[k];
    // Past its limit, a sequential check would have stopped inside this job, before any
    // failure it found (a job's own cap above is looser: it does not count the jobs before
    // it in this batch).
    work += j.work;
    const bool over = work > j.limit;
    if (!over && j.ended == Ended::Held) continue;
    // The first failure in record order: the queued jobs come after it and are dropped.
    failed_ = true;
    jobs_.clear();
    if (over || j.ended == Ended::OverWork) rejected(j.record, kTooMuchWork);
    if (j.ended == Ended::OutOfMemory) throw std::bad_alloc();
    ranks::broadcast(j.why, int(k / kRun % size_t(ranks::size())));  // from the rank that ran it
    if (j.ended == Ended::Failed) rejected(j.record, j.why);
    throw std::runtime_error(j.why);
  }
}

// Every rank learns how each job of the batch ended and the work it took (a job that is
// not this rank's holds zeros here, so a sum over the ranks gives everyone the lot).
void ProofBatch::share(std::vector<Job>& jobs) {
  if (ranks::size() == 1) return;
  std::vector<uint64_t> v(2 * jobs.size());
  for (size_t k = 0; k < jobs.size(); ++k) {
    v[2 * k] = jobs[k].work;
    v[2 * k + 1] = uint64_t(jobs[k].ended);
  }
  ranks::sum(v.data(), v.size());
  for (size_t k = 0; k < jobs.size(); ++k) {
    jobs[k].work = v[2 * k];
    jobs[k].ended = Ended(v[2 * k + 1]);
  }
}

void ProofBatch::flush() {
  if (failed_) return;
  finish();
  start();
  finish();
}

long ProofBatch::refutations() const {
  long s = 0;
  for (const auto& w : workers_) s += w->pr->refutations;
  return s;
}

long ProofBatch::refute_boxes() const {
  long s = 0;
  for (const auto& w : workers_) s += w->pr->refute_boxes;
  return s;
}

}  // namespace cc
