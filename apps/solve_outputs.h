// The outputs of `aspects solve --out DIR`: the certificate (its records were written
// while solving), boxes.csv, the result index read by `aspects query` and `aspects path`,
// and summary.json. Each file is complete or absent (written under a temporary name and
// renamed).
#pragma once

#include <memory>

#include "certificate_writer.h"
#include "generalized_aspects.h"
#include "model/model.h"
#include "solve_command.h"

namespace aspects {

// Creates the output directory (with --out) and opens the certificate, written while
// solving; null without --out or with --no-cert.
std::unique_ptr<CertificateWriter> open_outputs(const SolveOptions& o, const Model& model);

// Writes the certificate (when `cert` is not null), boxes.csv and the index at once, then
// summary.json with the time and memory of this phase appended to r's phases. Throws the
// first failure once all three have ended; summary.json is then not written.
void write_solve_outputs(const SolveOptions& o, const Model& model, CertificateWriter* cert,
                         AspectsResult& r);

}  // namespace aspects
