// Algorithm 1's steps for the NCSP (4) of paper 4.2: f = 0, det Fx ≠ 0, det Fq ≠ 0,
// assembled from parts handed in: a contractor (Prune), a solution-box prover (Prove), a
// bisector (Branch) and the additional constraints (paper 5.4). The steps store each leaf
// as an output box with its factor signs, stream the certificate's tree records, and count
// what decided each box.
#pragma once

#include <string>
#include <vector>

#include "certificate_sink.h"
#include "factor_signs.h"
#include "model/constraints.h"
#include "search/bisector.h"
#include "search/branch_and_prune.h"
#include "search/contractor.h"
#include "search/output_boxes.h"
#include "search/verdict.h"
#include "solution_box.h"

namespace aspects {

// Why the search decided what it did: for tuning and for the user, not for any claim.
struct SearchDiagnostics {
  VerdictCounts attempts{};   // Prove's verdict on every box that survived Prune
  VerdictCounts undecided{};  // the verdict on each undecided leaf
  long refuted_by_equation = 0, refuted_by_newton = 0, refuted_by_constraint = 0;
  void add(const SearchDiagnostics& o);
};

struct SearchParts {
  Contractor& contractor;
  BoxProver& prover;
  Bisector& bisector;
  ConstraintChecker& constraints;
  FactorSigns& signs;
};

class AspectsSearch : public BranchAndPruneSteps {
 public:
  // `equations`: n, for the discard reasons (certificates/FORMAT.md): equation i is i,
  // Hansen–Sengupta n, constraint c is n + 1 + c.
  AspectsSearch(int equations, SearchParts parts, OutputBoxes& out, SearchDiagnostics& diag,
                TreeSink* sink);

  PruneResult prune(Box& box) override;
  ProveResult prove(const Box& cell) override;
  int32_t keep_undecided(const Box& box, Verdict why, const PruneResult& pruned) override;
  int32_t keep_unexplored(const Box& cell) override;
  SplitChoice choose_split(const Box& box, const SplitContext& ctx) override;
  void branched(int var, double at) override;
  void deferred(int32_t task) override;

 private:
  PruneResult refuted(int32_t reason, const char* hint);
  int32_t store(const Box& box, bool certified, UndecidedKind kind);

  const int n_;
  SearchParts parts_;
  OutputBoxes& out_;
  SearchDiagnostics& diag_;
  TreeSink* sink_;
  std::vector<std::string> hints_;  // "eq0", "eq1", ...
  // Scratch, reused from box to box; nothing here outlives a call.
  Box cell_, reported_;
  SolutionProof proof_;
  std::vector<int8_t> signs_;
};

}  // namespace aspects
