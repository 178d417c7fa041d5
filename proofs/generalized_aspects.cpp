#include <memory>

#include "generalized_aspects.h"

#include "pipeline/csnc_phase.h"
#include "pipeline/link_phase.h"
#include "pipeline/parallel.h"
#include "pipeline/phase_clock.h"
#include "pipeline/search_phase.h"
#include "pipeline/separation_phase.h"
#include "pipeline/witness_phase.h"

namespace aspects {

namespace {

// The leaves' fates, counted on the merged tree (a resumed run did not process every node).
void count_leaves(AspectsResult& out) {
  for (const SearchNode& node : out.tree) {
    if (node.internal()) {
      ++out.processed;
      continue;
    }
    out.processed += node.fate != LeafFate::Unexplored;
    out.solutions += node.fate == LeafFate::Solution;
    out.undecided += node.fate == LeafFate::Undecided;
    out.discarded += node.fate == LeafFate::Discarded;
    out.unexplored += node.fate == LeafFate::Unexplored;
  }
}

}  // namespace

AspectsResult compute_aspects(Model& model, const AspectsConfig& config) {
  AspectsResult out;
  // The phase during which a stop was first seen: it and those after it are partial (a
  // spent max-boxes budget stops the search alone).
  PhaseClock clock([&](const std::string& phase, double seconds) {
    const bool search = phase == std::string("search");
    if (out.stopped_in.empty() && config.stop &&
        (search ? config.stop->stopped() : config.stop->poll()))
      out.stopped_in = phase;
    // The merge never stops (it assembles what was searched): the next phase is the cut one.
    if (!search && phase != std::string("merge") && out.run_stopped_in.empty() && config.stop &&
        config.stop->poll())
      out.run_stopped_in = phase;
    if (config.phase_done) config.phase_done(phase, seconds);
  });
  Parallel parallel(config.threads, working_precision());
  out.factors = determinant_factors(model);  // adds nodes: before any evaluator exists
  SearchOutcome searched = search_phase(model, config, out.factors, parallel, clock);
  out.boxes = std::move(searched.boxes);
  out.tree = std::move(searched.tree);
  // The later phases' results do not depend on the threads either (parallel.h).
  std::unique_ptr<Parallel> more;
  if (config.later_threads > config.threads)
    more = std::make_unique<Parallel>(config.later_threads, parallel.precision());
  Parallel& later = more ? *more : parallel;
  out.diagnostics = searched.diagnostics;
  count_leaves(out);

  // M streams through the links and the separation's first pass, never held whole.
  std::vector<bool> periodic;
  for (const auto& v : model.vars) periodic.push_back(v.periodic);
  LinkPhase links(model, config, out.boxes, later);
  SeparationPhase separation(out.boxes, later);
  const bool whole_graph = stream_neighbor_pairs(
      out.tree, out.boxes.ends(), periodic,
      [&](const std::vector<NeighborPair>& piece) {
        out.neighbor_count += piece.size();
        separation.add(piece);
        links.add(piece);
      },
      later.for_each(), [&] { return config.stopped(); });
  LinkOutcome linked = links.finish();
  out.neighbors = std::move(linked.neighbors);
  out.certified_links = std::move(linked.certified_links);
  out.link_proofs = std::move(linked.link_proofs);
  clock.lap("neighbourhood graph, separation and links");

  CsncOutcome csncs = csnc_phase(out.boxes, out.neighbors, out.certified_links);
  out.csnc = std::move(csncs.csnc);
  out.csnc_sizes = std::move(csncs.sizes);
  out.filtered = csncs.filtered;
  out.separation = separation.finish(whole_graph, out.tree, periodic, out.csnc, config);
  clock.lap("components and separation");

  out.cuspidal = witness_phase(model, config, periodic, out.boxes, out.csnc,
                               int(out.csnc_sizes.size()), later, clock);
  if (config.stop && config.stop->stopped()) out.stopped_by = config.stop->reason();
  out.seconds = clock.total_seconds();
  out.phase_seconds = clock.seconds();
  out.phase_peak_mib = clock.peak_mib();
  return out;
}

}  // namespace aspects
