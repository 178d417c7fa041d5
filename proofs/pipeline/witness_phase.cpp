#include "witness_phase.h"

#include <tbb/enumerable_thread_specific.h>

#include "assembly_witness.h"
#include "hansen_sengupta.h"
#include "model/model_eval.h"

namespace aspects {

CuspidalWitnesses witness_phase(const Model& model, const AspectsConfig& config,
                                const std::vector<bool>& periodic, const OutputBoxes& boxes,
                                const std::vector<int32_t>& csnc, int csncs, Parallel& parallel,
                                PhaseClock& clock) {
  CuspidalWitnesses w;
  const WitnessSpace space(model.pose, model.command, periodic);
  if (!config.stopped())
    w = find_pose_witnesses(boxes.ends(), csnc, csncs, space, 10000, parallel.for_each());
  clock.lap("cuspidality");
  if (config.stopped()) {
    clock.lap("assembly witnesses");
    return w;
  }
  struct AssemblyProver {
    ModelEvaluator ev;
    HsWorkspace ws;
    AssemblyProver(const Model& m, const AspectsConfig& c) : ev(m, c.arithmetic) {
      c.made(ev.arithmetic());
    }
  };
  tbb::enumerable_thread_specific<AssemblyProver> provers(
      [&] { return AssemblyProver(model, config); });
  auto prove = [&](CommandWitness& cw) {
    AssemblyProver& p = provers.local();
    return prove_command_witness(p.ev, boxes.ends(), config.tau, cw, p.ws);
  };
  find_command_witnesses(boxes.ends(), csnc, csncs, space, prove, w, 1000, 100000, 2,
                         parallel.for_each());
  clock.lap("assembly witnesses");
  return w;
}

}  // namespace aspects
