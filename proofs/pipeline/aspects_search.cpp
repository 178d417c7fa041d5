#include "aspects_search.h"

namespace aspects {

void SearchDiagnostics::add(const SearchDiagnostics& o) {
  for (int k = 0; k < kVerdicts; ++k) {
    attempts[k] += o.attempts[k];
    undecided[k] += o.undecided[k];
  }
  refuted_by_equation += o.refuted_by_equation;
  refuted_by_newton += o.refuted_by_newton;
  refuted_by_constraint += o.refuted_by_constraint;
}

AspectsSearch::AspectsSearch(int equations, SearchParts parts, OutputBoxes& out,
                             SearchDiagnostics& diag, TreeSink* sink)
    : n_(equations), parts_(parts), out_(out), diag_(diag), sink_(sink),
      signs_(parts.signs.factors()) {
  for (int i = 0; i < n_; ++i) hints_.push_back("eq" + std::to_string(i));
}

PruneResult AspectsSearch::refuted(int32_t reason, const char* hint) {
  if (sink_) sink_->discard(hint);
  PruneResult r;
  r.refuted_by = reason;
  return r;
}

// Prune: the contraction, recorded for the certificate, then the constraints: a box where
// one certainly fails holds no feasible configuration (paper 5.4).
PruneResult AspectsSearch::prune(Box& box) {
  if (sink_) cell_ = box;  // for the contraction records only
  if (Refutation r = parts_.contractor.contract(box)) {
    if (r.kind == Refutation::Equation) {
      ++diag_.refuted_by_equation;
      return refuted(r.equation, hints_[r.equation].c_str());
    }
    ++diag_.refuted_by_newton;
    return refuted(n_, "hs");
  }
  if (sink_)
    for (size_t v = 0; v < box.size(); ++v) {
      double lo = box[v].lo_down(), hi = box[v].hi_up();
      if (lo > cell_[v].lo_down() || hi < cell_[v].hi_up()) sink_->contraction(int(v), lo, hi);
    }
  int violated = -1;
  PruneResult kept;
  kept.constraints = parts_.constraints.evaluate(box, &violated);
  if (kept.constraints == Truth::False) {
    ++diag_.refuted_by_constraint;
    return refuted(n_ + 1 + violated, ("c" + std::to_string(violated)).c_str());
  }
  return kept;
}

ProveResult AspectsSearch::prove(const Box& cell) {
  const Verdict v = parts_.prover.prove(cell, reported_, proof_);
  ++diag_.attempts[int(v)];
  if (v != Verdict::Solution) return {v};
  const int32_t index = store(reported_, true, UndecidedKind::NoExistence);
  if (sink_) sink_->solution(index, signs_.data(), proof_);
  return {v, index};
}

int32_t AspectsSearch::keep_undecided(const Box& box, Verdict why, const PruneResult& pruned) {
  ++diag_.undecided[int(why)];
  const bool on_constraint =
      pruned.constraints == Truth::Unknown || why == Verdict::ConstraintBoundary;
  const bool p2 = why == Verdict::SingularFx || why == Verdict::SingularFq;
  const int32_t index = store(box, false,
                              on_constraint ? UndecidedKind::Constraint
                              : p2          ? UndecidedKind::Singular
                                            : UndecidedKind::NoExistence);
  if (sink_) sink_->undecided(index, signs_.data());
  return index;
}

int32_t AspectsSearch::keep_unexplored(const Box& cell) {
  const int32_t index = store(cell, false, UndecidedKind::Unexplored);
  if (sink_) sink_->unexplored(index, signs_.data());
  return index;
}

SplitChoice AspectsSearch::choose_split(const Box& box, const SplitContext& ctx) {
  return parts_.bisector.choose(box, ctx);
}

void AspectsSearch::branched(int var, double at) {
  if (sink_) sink_->split(var, at);
}

void AspectsSearch::deferred(int32_t task) {
  if (sink_) sink_->deferred(task);
}

int32_t AspectsSearch::store(const Box& box, bool certified, UndecidedKind kind) {
  parts_.signs.of(box, signs_.data());
  return out_.push(box, certified, kind, signs_.data());
}

}  // namespace aspects
