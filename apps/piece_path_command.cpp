#include "piece_path_command.h"

#include <iostream>

#include "counting/factor_gradients.h"
#include "piece_path.h"
#include "piece_path_output.h"
#include "results/pose.h"
#include "results/usage_error.h"

namespace aspects {

int run_piece_path(const PathOptions& opts) {
  if (opts.csnc >= 0)
    throw UsageError("--csnc: " + opts.result_dir + " is a count directory (written by "
                     "`aspects count --out`), which has pieces, not CSNCs: use --class");
  if (!opts.out.empty() || !opts.plot.empty())
    throw UsageError(std::string(opts.out.empty() ? "--plot" : "--out") +
                     ": not available for a path through a count's pieces (use --json)");
  CountDirectory d = load_count_directory(opts.result_dir);
  const int64_t cls = parse_class_signs(opts.cls, int(d.pieces.factors.size()));
  const std::vector<double> from = parse_pose(opts.from, "--from", d.model);
  const std::vector<double> to = parse_pose(opts.to, "--to", d.model);
  // The gradients' nodes are added to the model before its evaluator exists.
  FactorGradients fg(d.model, d.factor_nodes);
  ModelEvaluator ev(d.model);
  const PiecePathResult r = plan_piece_path(d, ev, fg, from, to, cls);
  if (opts.json)
    std::cout << piece_path_json(d, from, to, r).dump() << '\n';
  else
    std::cout << piece_path_text(d, from, to, r);
  return r.outcome == PiecePathOutcome::Found ? 0 : 1;
}

}  // namespace aspects
