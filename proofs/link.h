// Property P3 (paper 4.3.2, equation (10)): two solution boxes A and B are linked when
//   ∃ q ∈ [q_A] ∩ [q_B], f(x̂, q) = 0  with x̂ a point of [x_A] ∩ [x_B]
// (intersections modulo 2π on periodic variables; f is 2π-periodic in them). Then
// Σ(A) ∩ Σ(B) ≠ ∅ and both lie in the same aspect. x̂ is a double chosen inside the
// inner-rounded intersection; the existence is proved by iteration (9) at the point x̂,
// and the proved enclosure must lie inside the inner-rounded [q_A] ∩ [q_B].
#pragma once

#include <vector>

#include "search/box_store.h"
#include "hansen_sengupta.h"
#include "aspects/neighborhood_graph.h"

namespace aspects {

struct LinkProof {
  std::vector<double> witness;   // x̂, one double per pose variable (model pose order)
  std::vector<Interval> common;  // inner [q_A] ∩ ([q_B] + 2πk), per command
  ExistenceProof existence;      // iteration (9) at x̂
};

// Inner-rounded intersection of a and b + 2πk (k = 0 for non-periodic variables):
// every double in [lo, hi] lies in a and, minus 2πk, in b. False when empty.
bool inner_intersection(double alo, double ahi, double blo, double bhi, int k, double& lo,
                        double& hi);

// The numbers of certified links that the certificate records (certificates/FORMAT.md,
// `K`), kept as exact doubles: per link the witness x̂ (n), the inflated iterate [q~]
// (n intervals, lo then hi) and the preconditioner C (n×n, row major). A LinkProof holds
// MPFI intervals, about ten times the memory. Past kSpillBytes the records go to an unnamed
// temporary file (in $TMPDIR, else /tmp) and only the last ones stay in memory: 3-RPR at
// eps 0.1 certifies 38 M links, 5.5 GB of records needed only when the certificate is
// written (proofs/link_records.cpp).
class LinkRecords {
 public:
  static constexpr size_t kSpillBytes = size_t(8) << 20;
  explicit LinkRecords(int n = 0) : n_(n) {}
  LinkRecords(const LinkRecords& o);
  LinkRecords& operator=(const LinkRecords& o);
  LinkRecords(LinkRecords&& o) noexcept;
  LinkRecords& operator=(LinkRecords&& o) noexcept;
  ~LinkRecords();

  void push(const LinkProof& p);
  void append_one(const LinkRecords& o, size_t i) { add(o.record(i)); }
  size_t size() const { return size_; }
  // The reads go through a cache of spilled records, one per thread: the certificate and
  // the result index read them at once (run/solve_outputs.cpp). A pointer returned stays
  // valid until the same thread's next read.
  const double* witness(size_t i) const { return record(i); }
  double inflated_lo(size_t i, int j) const { return record(i)[n_ + 2 * j]; }
  double inflated_hi(size_t i, int j) const { return record(i)[n_ + 2 * j + 1]; }
  const double* C(size_t i) const { return record(i) + 3 * n_; }
  int n() const { return n_; }
  size_t spilled() const { return spilled_; }  // records in the file

 private:
  size_t stride() const { return size_t(3 * n_ + n_ * n_); }
  void add(const double* rec);
  void spill();
  const double* record(size_t i) const;
  int n_;
  size_t size_ = 0, spilled_ = 0;  // records; of which in the file
  std::vector<double> tail_;       // records spilled_ .. size_ - 1
  int fd_ = -1;
  // Names this object's records for the per-thread caches (a new one whenever they change
  // owner: a cache is never reused for another object's records).
  uint64_t serial_ = next_serial();
  static uint64_t next_serial();
};

// With `grid`, the witness and Q~ are chosen on the grids of box A that format 3 codes
// them against (proofs/certificate_grid.h), where the intersection allows.
bool certify_link(ModelEvaluator& ev, const BoxStore& R, const NeighborPair& pair, double tau,
                  LinkProof& proof, HsWorkspace& ws, bool grid = false);

}  // namespace aspects
