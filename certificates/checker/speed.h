// speed.h — speed layer: the declarations of the optional parts of check_cert that make it
// fast, each tested against the trusted core (checker.h) and off with --trusted-only, except
// the ranks, which without MPI are one process: the proofs on T threads and P processes
// (proof_batch.cpp, ranks.cpp) and the strip sweep of the graph M (fast_sweep.cpp). The
// doubles path of the interval type and the evaluator's have headers of their own
// (interval_doubles.h; checker.h, whose Evaluator holds eval_speed.cpp's state).
#pragma once

#include <atomic>
#include <thread>

#include "checker.h"

namespace cc {

// ---- The interval proofs on T threads (proof_batch.cpp): check.cpp decides each record's
// structure itself and queues its proofs; a batch runs on every thread (each with its own
// evaluator and prover) and is judged in record order, so the verdict is that of one
// thread: the first failed proof in record order, the work limit charged job by job.
class ProofBatch {
 public:
  // A proof on one thread's prover: "" when it holds, else why not (the rejection reason).
  using Proof = std::function<std::string(Prover&)>;
  // `work_before`: the node evaluations the check did before its first proof.
  ProofBatch(const Model& m, int threads, uint64_t work_before);
  ~ProofBatch();
  // Queues the proof of `record`; `limit` is the work the check may have done by its end.
  void add(long record, uint64_t limit, Proof proof);
  // Runs every queued proof; throws the rejection of the first that failed, in record
  // order. After a failure has been thrown, does nothing (later proofs cannot come first).
  void flush();
  long refutations() const;
  long refute_boxes() const;
  uint64_t work;  // node evaluations so far, judged proofs included

 private:
  struct Worker;
  struct Job;
  void work_on(int t);
  void start();
  void finish();
  static void share(std::vector<Job>& jobs);
  const mpfr_prec_t prec_;
  const size_t batch_;  // jobs per batch
  std::vector<std::unique_ptr<Worker>> workers_;
  std::vector<Job> jobs_;     // queued, being filled by the reader
  std::vector<Job> running_;  // the batch the threads work on
  std::atomic<size_t> next_{0};
  bool failed_ = false;  // a proof failed: it is the verdict, nothing after it is judged
  std::vector<std::thread> helpers_;  // running the batch beside this thread
};

// ---- The processes of `mpirun -n P check_cert` (ranks.cpp): one without MPI.
namespace ranks {
// MPI_Init in the MPI build; else a reason to refuse a run under an MPI launcher ("" none).
std::string start(int* argc, char*** argv);
void stop();
[[noreturn]] void abort_all(const std::string& why);  // this rank failed alone: end the job
int rank();
int size();
// The first rank whose executable, certificate or `options` differ from rank 0's; -1: none.
int differing_rank(const std::string& cert, const std::string& options);
void sum(uint64_t* v, size_t n);     // element-wise over the ranks, the result on every rank
void broadcast(std::string& s, int root);
}  // namespace ranks

// ---- The fast sweep of M (fast_sweep.cpp): PlainSweep's pairs, from items of floats
// rounded outward, in strips of a second variable swept on T threads.
class NeighbourSweep : public PairSweep {
 public:
  NeighbourSweep(const OutBoxes& R, const std::vector<bool>& periodic, const Ival& two_pi);
  size_t run(const std::function<void(int, int)>& visit, size_t max_pairs = SIZE_MAX,
             int threads = 1) const override;
  // Boxes whose shifted ends are held: those whose copy shifted by ±2π meets the hull.
  size_t seam_boxes() const { return P_ ? shifted_.size() / (2 * P_) : 0; }

 private:
  static constexpr int kMaxStrips = 1 << 16;  // so that a strip's index fits Item::strip
  // Ends as floats rounded outward: a superset of the true overlaps, which run() then
  // tests on the boxes' doubles (32 bytes an item, where doubles would take 56).
  struct Item {
    float lo, hi;    // on d, shifted by 2πk
    float elo, ehi;  // on e (the whole line if there is no e)
    float glo, ghi;  // on g (likewise)
    int32_t id;
    int16_t k;
    uint16_t strip;  // the strip of elo: a pair's strip is the larger of its two
  };
  const OutBoxes& R_;
  std::vector<int> slot_;  // per variable: its column in a row of shifted_, -1 if not periodic
  // Only a box whose shifted copy meets the hull of the boxes on some periodic variable (a
  // box on a seam) has a row: row_[b] (-1: none), and shifted_[(row·P + slot)·2 + (k > 0)]
  // holds the ends of b_v + 2πk, k = ±1, rounded outward. A copy that misses the hull
  // meets no box.
  std::vector<int32_t> row_;
  std::vector<std::array<double, 2>> shifted_;
  const std::array<double, 2>* shifted(int b, int v, int k) const {
    return row_[b] < 0 ? nullptr : &shifted_[(size_t(row_[b]) * P_ + slot_[v]) * 2 + (k > 0)];
  }
  size_t P_ = 0;  // periodic variables
  int strip(double e) const;
  // The pairs of strip t, each handed to `put` (returns false to stop: the pair limit).
  bool sweep_strip(int t, const std::function<bool(int, int)>& put) const;
  double e_lo_ = 0, e_width_ = 1;  // strips of the second sweep variable e: [lo + t·w, ...)
  int g_ = -1;                     // a third variable, tested in the items; maybe periodic
  bool g_apart(const Item& p, const Item& q) const;
  int strips_ = 1;
  std::vector<size_t> strip_start_;  // items_ of strip t: [strip_start_[t], strip_start_[t+1])
  std::vector<Item> items_;          // by strip, then by lo
};

}  // namespace cc
