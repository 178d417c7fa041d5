// `aspects solve --resume DIR`: the options of the resumed run come from the checkpoint's
// header; an option given again must agree with it (else CheckpointError, exit 2), so a
// state is never mixed with another model, eps, precision or program version.
#pragma once

#include <memory>

#include "certificate_writer.h"
#include "checkpoint.h"
#include "generalized_aspects.h"
#include "model/model.h"
#include "solve_command.h"

namespace aspects {

// With --resume DIR: reads DIR's checkpoint, takes the run's options from it (see
// adopt_checkpoint) and removes the temporaries a killed run left there. Null without
// --resume.
std::unique_ptr<Checkpoint> open_resumed_run(SolveOptions& o);

// Hands the checkpoint's state to the engine (its finished parts are not searched again,
// the tree keeps the checkpoint's cut) and puts the certificate records of those parts
// back into `cert` (null: no certificate).
void resume_search(Checkpoint& resumed, CertificateWriter* cert, AspectsConfig& cfg);

// Sets o's eps, precision, tau, bisector, links mode, certificate, output directory and
// checkpoint interval from h (refusing a version or explicit option that differs).
void adopt_checkpoint(SolveOptions& o, const CheckpointHeader& h);

// The model of the resumed run: MODEL when given again (its text must hash as the
// checkpoint's), else the model text the checkpoint holds.
Model resumed_model(const SolveOptions& o, const CheckpointHeader& h);

// Removes the temporary files a killed run left in `dir` (outputs and checkpoint written
// under NAME.tmp.PID...) when process PID no longer exists; returns how many.
int remove_stale_temporaries(const std::string& dir);

}  // namespace aspects
