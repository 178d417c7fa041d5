// The outputs of `aspects solve --out DIR`: the certificate (its records were written
// while solving), boxes.csv, the result index read by `aspects query` and `aspects path`,
// and summary.json. Each file is complete or absent (written under a temporary name and
// renamed); the directory holds the files of one run only: it is locked for the whole run
// (DIR/.lock), and a run removes the files of the run before it. The index and the
// summary record the certificate's hash (results/result_files.h).
#pragma once

#include <memory>

#include "certificate_writer.h"
#include "generalized_aspects.h"
#include "io/directory_lock.h"
#include "model/model.h"
#include "run/solve_options.h"
#include "run/summary_json.h"

namespace aspects {

// The directory a run writes: --out, or the directory of --resume (empty: none).
std::string output_directory(const SolveOptions& o);

// Creates the output directory and locks it, for as long as the returned lock lives (take
// it before reading a checkpoint there). Null without an output directory. Throws
// UsageError, before creating anything, for a path with a NUL character, and when another
// run holds the lock; a filesystem without locks gets a warning on stderr, no lock.
std::unique_ptr<DirectoryLock> lock_outputs(const SolveOptions& o);

// Removes the temporary files a killed run left in `dir` (outputs and checkpoint written
// under NAME.tmp.PID...) when process PID no longer exists; returns how many.
int remove_stale_temporaries(const std::string& dir);

// Removes the outputs of the run that wrote the directory before (all of them: a run
// rewrites those it writes; the checkpoint stays when resuming from it) and the
// temporaries a killed run left, then opens the certificate, written while solving; null
// without --out or with --no-cert. Call it with the directory locked.
std::unique_ptr<CertificateWriter> open_outputs(const SolveOptions& o, const Model& model);

// Writes the certificate (when `cert` is not null), boxes.csv and the index at once, then
// summary.json with the time and memory of this phase appended to r's phases. Throws the
// first failure once all three have ended; summary.json is then not written. Returns the
// hashes the index and the summary record.
OutputHashes write_solve_outputs(const SolveOptions& o, const Model& model,
                                 CertificateWriter* cert, AspectsResult& r);

}  // namespace aspects
