// Phase 5, cuspidality witnesses (paper 3.2) inside each CSNC, both kinds: "one pose, two
// commands" (aspects/cuspidality.h), then "one command, two poses" (assembly-mode changes),
// each proved in x at a point (proofs/assembly_witness.h). The CSNCs are searched in
// parallel; the witnesses are the same for any number of threads. Every witness found is
// proved; none is claimed to be the only one. Stopped, a search not begun is skipped.
#pragma once

#include <cstdint>
#include <vector>

#include "aspects/cuspidality.h"
#include "aspects_config.h"
#include "model/model.h"
#include "parallel.h"
#include "phase_clock.h"
#include "search/output_boxes.h"

namespace aspects {

// Laps "cuspidality" and "assembly witnesses" on `clock`.
// `periodic`: per variable, as the neighbourhood graph took it.
CuspidalWitnesses witness_phase(const Model& model, const AspectsConfig& config,
                                const std::vector<bool>& periodic, const OutputBoxes& boxes,
                                const std::vector<int32_t>& csnc, int csncs, Parallel& parallel,
                                PhaseClock& clock);

}  // namespace aspects
