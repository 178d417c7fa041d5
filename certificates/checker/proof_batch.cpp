// proof_batch.cpp — speed layer: the interval proofs of a check on T threads. The record
// rules (check.cpp) read every record and decide its structure themselves, in order; each
// interval proof (a refutation, a Hansen–Sengupta step, a regularity test, a factor sign)
// becomes a job of a batch. A batch runs on every thread, each with its own evaluator and
// prover, and is then judged in record order, so the verdict, the record it names and its
// reason are those of one thread, whatever T is: the first failed proof in record order
// wins, and the work limit is charged job by job in record order as a sequential check
// charges it.
#include <flint/flint.h>

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <memory>

#include "checker.h"

namespace cc {

namespace {
// Jobs per batch: enough to share, few enough to hold. CHECK_CERT_BATCH changes it (the
// tests use tiny batches, so that many boundaries fall between a proof and its record's
// structural checks); it changes how the work is shared, never the verdict.
size_t batch_size() {
  const char* e = std::getenv("CHECK_CERT_BATCH");
  const long v = e ? std::atol(e) : 0;
  return v >= 1 && v <= (1 << 20) ? size_t(v) : 1024;
}
}  // namespace

struct ProofBatch::Worker {
  std::unique_ptr<Evaluator> ev;
  std::unique_ptr<Prover> pr;
};

struct ProofBatch::Job {
  long record;
  uint64_t limit;  // the work a sequential check may have done by the end of this job
  Proof proof;
  std::string failure;       // why the proof failed ("" if it held)
  std::exception_ptr error;  // what it threw (the work limit, out of memory)
  uint64_t work = 0;         // node evaluations it took
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
  jobs_.push_back(Job{record, limit, std::move(proof), {}, nullptr, 0});
  if (jobs_.size() < batch_) return;
  finish();
  start();
}

// Jobs of the running batch, a run of consecutive ones at a time (neighbouring records
// share boxes, which the evaluator's caches keep), on worker t, until none is left.
void ProofBatch::work_on(int t) {
  Worker& w = *workers_[t];
  const size_t run = 32, N = running_.size();
  for (size_t i; (i = next_.fetch_add(run)) < N;)
    for (size_t k = i; k < std::min(N, i + run); ++k) {
      Job& j = running_[k];
      // Stopped where a sequential check, having done `work` before this batch, would be
      // stopped at the latest; the judgement charges the jobs before it too.
      w.ev->work = 0;
      w.ev->work_limit = j.limit > work ? j.limit - work : 0;
      try {
        j.failure = j.proof(*w.pr);
      } catch (...) {
        j.error = std::current_exception();
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
  for (Job& j : jobs) {
    // Past its limit, a sequential check would have stopped inside this job, before any
    // failure it found (a job's own cap above is looser: it does not count the jobs before
    // it in this batch).
    work += j.work;
    const bool over = work > j.limit;
    if (!over && j.failure.empty() && !j.error) continue;
    // The first failure in record order: the queued jobs come after it and are dropped.
    failed_ = true;
    jobs_.clear();
    if (over) rejected(j.record, kTooMuchWork);
    if (!j.failure.empty()) rejected(j.record, j.failure);
    std::rethrow_exception(j.error);
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
