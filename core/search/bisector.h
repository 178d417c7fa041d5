// Branch of Algorithm 1: which variable of a box to bisect, and where. A bisector is a
// policy, chosen per run; the search loop only asks it. Every bisector here keeps the
// paper's meaning of eps: a box is bisected while its widest variable is wider than eps
// (and only then); which variable is cut is the bisector's choice. One exception: a
// variable with no double strictly inside it (eps below the doubles' spacing there, as with
// eps 1e-300 on a cell near 1) cannot be cut, and a box with no other variable to cut is a
// leaf (an undecided box wider than eps, which check_cert counts as `wide_undecided`). A
// cut at one of its ends would make a child equal to its parent, again and again, without
// end.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "numerics/interval.h"
#include "model/model.h"
#include "search/verdict.h"

namespace aspects {

// A variable the search may cut: wider than eps, with a double strictly inside it.
bool splittable(const Interval& x, double eps);

struct SplitChoice {
  int var = -1;     // -1: no variable is splittable(); the box is a leaf
  double at = 0;    // exact split point, strictly inside the variable's interval
};

struct SplitContext {
  int parent_split = -1;  // the variable bisected to make this box (-1 at the root)
  Verdict verdict = Verdict::NoExistence;  // why Prove failed on this box
};

class Bisector {
 public:
  virtual ~Bisector() = default;
  SplitChoice choose(const Box& box, const SplitContext& ctx) const;
  // Where a variable is cut: lo + fraction·width (the middle by default). The count's first
  // cover cuts off the middle, so that no cut lies on a plane of symmetry of the model,
  // where singular curves meet a cut and a seam in one point (proofs/counting/exact_count.h).
  void set_split_fraction(double fraction) { fraction_ = fraction; }

 protected:
  Bisector(const Model& m, double eps) : m_(m), eps_(eps) {}
  // A variable to bisect; called only when some variable is wider than eps.
  virtual int variable(const Box& box, const SplitContext& ctx) const = 0;
  const Model& m_;
  double eps_;
  double fraction_ = 0.5;
};

enum class BisectorKind {
  RoundRobin,  // the paper (4.2.3): the variables in turn
  PoseFirst,   // the widest pose variable, the commands once the pose is narrow
  Verdict,     // what blocked the proof: the pose when P2 failed or the pose spread P1,
               // else round robin
};

// Parses "round-robin", "pose-first", "verdict"; false for anything else.
bool parse_bisector_kind(const std::string& name, BisectorKind& kind);

std::unique_ptr<Bisector> make_bisector(BisectorKind kind, const Model& m, double eps);

}  // namespace aspects
