// summary.json of `aspects solve --out`: the run's options, counts, phases, CSNCs, the
// separated lower bound, the cuspidality witnesses, the factors and the search's
// diagnostics. A report for people and scripts; the claims are proved in the certificate.
#pragma once

#include <nlohmann/json.hpp>

#include "generalized_aspects.h"
#include "model/model.h"
#include "results/result_index.h"
#include "run/solve_options.h"

namespace aspects {

// What ties summary.json to the other files of its directory (results/result_files.h).
struct OutputHashes {
  CertificateId certificate;  // empty: none (--no-cert, or no directory)
  std::string index_sha256;   // empty: no index written
};

// With the model's hash, and the certificate's and the index's (null when empty).
nlohmann::json summary_json(const Model& m, const SolveOptions& o, const AspectsResult& r,
                            const OutputHashes& hashes = {});

}  // namespace aspects
