// Property P3 (paper 4.3.2, equation (10)): two solution boxes A and B are linked when
//   ∃ q ∈ [q_A] ∩ [q_B], f(x̂, q) = 0  with x̂ a point of [x_A] ∩ [x_B]
// (intersections modulo 2π on periodic variables; f is 2π-periodic in them). Then
// Σ(A) ∩ Σ(B) ≠ ∅ and both lie in the same aspect. x̂ is a double chosen inside the
// inner-rounded intersection; the existence is proved by iteration (9) at the point x̂,
// and the proved enclosure must lie inside the inner-rounded [q_A] ∩ [q_B].
#pragma once

#include <vector>

#include "box_store.h"
#include "hansen_sengupta.h"
#include "neighborhood_graph.h"

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
// `K`), kept as exact doubles in one array: per link the witness x̂ (n), the inflated
// iterate [q~] (n intervals, lo then hi) and the preconditioner C (n×n, row major). A
// LinkProof holds MPFI intervals, about ten times the memory; runs with millions of links
// keep these instead.
class LinkRecords {
 public:
  explicit LinkRecords(int n = 0) : n_(n) {}
  void push(const LinkProof& p);
  void append(const LinkRecords& o) { data_.insert(data_.end(), o.data_.begin(), o.data_.end()); }
  void append_one(const LinkRecords& o, size_t i) {
    data_.insert(data_.end(), o.data_.begin() + i * stride(), o.data_.begin() + (i + 1) * stride());
  }
  size_t size() const { return n_ ? data_.size() / stride() : 0; }
  const double* witness(size_t i) const { return &data_[i * stride()]; }
  double inflated_lo(size_t i, int j) const { return data_[i * stride() + n_ + 2 * j]; }
  double inflated_hi(size_t i, int j) const { return data_[i * stride() + n_ + 2 * j + 1]; }
  const double* C(size_t i) const { return &data_[i * stride() + 3 * n_]; }
  int n() const { return n_; }

 private:
  size_t stride() const { return size_t(3 * n_ + n_ * n_); }
  int n_;
  std::vector<double> data_;
};

bool certify_link(ModelEvaluator& ev, const BoxStore& R, const NeighborPair& pair, double tau,
                  LinkProof& proof, HsWorkspace& ws);

}  // namespace aspects
