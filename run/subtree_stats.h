// `aspects solve --subtree-stats FILE`: what each part of the search cost, one CSV row per
// part, for the scaling study of the distributed search (bench/scaling_replay.py replays
// the scheduler on these rows). Observes only: the result is the same with or without it.
//
// FILE's columns:
//   part            top (one row: the top of the tree, searched before the subtrees),
//                   level (one row per depth above the cut: the top's boxes at that depth,
//                   so a replay can cut the same tree higher up) or subtree (one row per
//                   deferred subtree, in task order = depth first)
//   task            the subtree's index (-1 for the top and its levels)
//   depth, path     the subtree's depth and its path from the root, one digit per
//                   bisection: 0 the lower half, 1 the upper (empty for the top)
//   nodes           the boxes the part processed (its tree's nodes; a deferred leaf of the
//                   top is its subtree's root, counted there): those of the top and the
//                   subtrees sum to summary.json's `processed`; a level's, to the top's
//   output_boxes    the part's boxes in R = S ∪ U (with the top's, summary.json's total)
//   cpu_seconds     the searching thread's CPU seconds; wall_seconds its wall seconds
//                   (empty for a part another process searched)
//   part_bytes      the part's encoding in an MPI message (run/search_part_codec.h)
//   decode_seconds  the seconds to read that encoding back, as an MPI job's rank 0 does
//                   for every part on one thread
//   message_bytes   what another process sent for it: the part's message and its
//                   certificate records (in that message, or later when rank 0 fetches
//                   them: distribution/mpi_subtrees.h); empty for a part searched here
//   searched_by     here, or remote (another process of an MPI job)
#pragma once

#include <mutex>
#include <string>
#include <vector>

#include "pipeline/aspects_config.h"

namespace aspects {

class SubtreeStats {
 public:
  explicit SubtreeStats(std::string path) : path_(std::move(path)) {}
  SubtreeStats(const SubtreeStats&) = delete;
  SubtreeStats& operator=(const SubtreeStats&) = delete;

  // Sets cfg.subtree_observer to fill the rows; this object must outlive the search.
  void attach(AspectsConfig& cfg);
  // FILE, atomically (a temporary name, then renamed).
  void write() const;

 private:
  struct Row {
    int depth = 0;
    std::string path;
    long nodes = -1;  // -1: not searched (a stopped run)
    long output_boxes = 0;
    double cpu_seconds = -1, wall_seconds = -1;  // -1: not known here
    long part_bytes = 0;
    double decode_seconds = 0;
    long message_bytes = -1;  // -1: searched here
  };
  void top_searched(const SearchState& st, const PartWork& work);
  void part_done(int32_t task, const SearchPart& part, const PartWork* work, long message);
  std::string path_;
  std::mutex lock_;  // the subtrees' rows are filled from several threads
  uint32_t nv_ = 0, p_ = 0;  // the model's variables and factors (from the top)
  Row top_;
  std::vector<Row> levels_;  // the top's nodes and output boxes at each depth
  std::vector<Row> subtrees_;
};

}  // namespace aspects
