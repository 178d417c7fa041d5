// summary.json of `aspects solve --out`: the run's options, counts, phases, CSNCs, the
// separated lower bound, the cuspidality witnesses, the factors and the search's
// diagnostics. A report for people and scripts; the claims are proved in the certificate.
#pragma once

#include <nlohmann/json.hpp>

#include "generalized_aspects.h"
#include "model/model.h"
#include "solve_command.h"

namespace aspects {

nlohmann::json summary_json(const Model& m, const SolveOptions& o, const AspectsResult& r);

}  // namespace aspects
