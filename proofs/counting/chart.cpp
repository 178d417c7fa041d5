#include "counting/chart.h"

namespace aspects {

void chart_variables(const Model& m, ChartKind kind, std::vector<int>& u, std::vector<int>& w) {
  u = kind == ChartKind::Pose ? m.pose : m.command;
  w = kind == ChartKind::Pose ? m.command : m.pose;
}

ChartVerdict prove_chart(ModelEvaluator& ev, const Box& box, ChartKind kind, HsWorkspace& ws,
                         Chart& chart) {
  const int n = ev.n();
  chart.kind = kind;
  chart_variables(ev.model(), kind, chart.u, chart.w);
  // hansen_sengupta's unknowns are the commands, or the pose with in_pose.
  const bool in_pose = kind == ChartKind::Command;
  std::vector<Interval> image;
  if (hansen_sengupta(ev, box, true, image, ws, in_pose) == HsStatus::NoSolution)
    return ChartVerdict::NoSolution;
  ExistenceProof proof;
  if (prove_existence(ev, box, 1.01, 8, proof, ws, in_pose) != Existence::Proved)
    return ChartVerdict::NotProved;
  // Uniqueness holds in W̃: it must hold the box's W for the graph to hold every solution.
  for (int j = 0; j < n; ++j)
    if (!proof.inflated[j].contains(box[chart.w[j]])) return ChartVerdict::NotProved;
  chart.w_range = proof.image;
  return ChartVerdict::Proved;
}

}  // namespace aspects
