#include "search/verdict.h"

namespace aspects {

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::Solution: return "solution";
    case Verdict::NoExistence: return "no_existence";
    case Verdict::WidePose: return "wide_pose";
    case Verdict::NotCovering: return "not_covering";
    case Verdict::OutsideDomain: return "outside_domain";
    case Verdict::SingularFx: return "singular_fx";
    case Verdict::SingularFq: return "singular_fq";
    case Verdict::ConstraintBoundary: return "constraint_boundary";
  }
  return "?";
}

}  // namespace aspects
