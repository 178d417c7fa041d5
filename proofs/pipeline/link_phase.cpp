#include "link_phase.h"

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <unordered_map>

#include "model/model_eval.h"

namespace aspects {

namespace {

constexpr size_t kBlock = 4096, kRoundPairs = 8 * kBlock;

// Joins made by one block during a round, with path compression (without it the chains
// grow with the block's links).
class LocalJoins {
 public:
  int32_t root(int32_t x) {
    int32_t r = x;
    for (auto it = up_.find(r); it != up_.end(); it = up_.find(r)) r = it->second;
    for (auto it = up_.find(x); it != up_.end() && it->second != r; it = up_.find(x)) {
      x = it->second;
      it->second = r;
    }
    return r;
  }
  void join(int32_t a, int32_t b) { up_[a] = b; }

 private:
  std::unordered_map<int32_t, int32_t> up_;
};

}  // namespace

LinkPhase::LinkPhase(const Model& m, const AspectsConfig& c, const OutputBoxes& boxes,
                     Parallel& parallel)
    : m_(m), c_(c), boxes_(boxes), parallel_(parallel), prec_(working_precision()) {
  out_.link_proofs = LinkRecords(m.n());
  const int joinable = c.all_links ? 0 : boxes.size();
  rank_.assign(joinable, 0);
  parent_.resize(joinable);
  boost::disjoint_sets<uint8_t*, int*> joined(rank_.data(), parent_.data());
  for (int b = 0; b < joinable; ++b) joined.make_set(b);
}

// During a round the blocks read `parent_` without path compression.
int32_t LinkPhase::joined_root(int32_t x) const {
  while (parent_[x] != x) x = parent_[x];
  return x;
}

void LinkPhase::add(const std::vector<NeighborPair>& piece) {
  for (const NeighborPair& pr : piece)
    if (boxes_.certified(pr.a) && boxes_.certified(pr.b)) candidates_.push_back(pr);
  while (candidates_.size() - first_ >= kRoundPairs && !c_.stopped()) round(kRoundPairs);
  candidates_.erase(candidates_.begin(), candidates_.begin() + first_);
  first_ = 0;
}

LinkOutcome LinkPhase::finish() {
  if (!c_.stopped()) round(candidates_.size() - first_);
  std::vector<NeighborPair>().swap(candidates_);
  return std::move(out_);
}

// The links among candidates_[first_, first_ + count), which are then done.
void LinkPhase::round(size_t count) {
  const size_t blocks = (count + kBlock - 1) / kBlock;
  std::vector<std::vector<int32_t>> block_links(blocks);
  std::vector<LinkRecords> block_proofs(blocks, LinkRecords(m_.n()));
  parallel_.arena().execute([&] {
    tbb::parallel_for(size_t(0), blocks, [&](size_t k) {
      set_working_precision(prec_);
      ModelEvaluator ev(m_, c_.arithmetic);
      c_.made(ev.arithmetic());
      HsWorkspace ws;
      LinkProof lp;
      LocalJoins local;
      const size_t end = first_ + std::min(count, (k + 1) * kBlock);
      for (size_t e = first_ + k * kBlock; e < end; ++e) {
        const auto& pr = candidates_[e];
        int32_t ra = 0, rb = 0;
        if (!c_.all_links) {
          ra = local.root(joined_root(pr.a));
          rb = local.root(joined_root(pr.b));
          if (ra == rb) continue;
        }
        if (!certify_link(ev, boxes_.ends(), pr, c_.tau, lp, ws, c_.grid_records)) continue;
        if (!c_.all_links) local.join(ra, rb);
        block_links[k].push_back(int32_t(e));
        if (c_.keep_link_proofs) block_proofs[k].push(lp);
      }
    });
  });
  // In order; a link joining what another block of the round already joined is dropped.
  boost::disjoint_sets<uint8_t*, int*> joined(rank_.data(), parent_.data());
  for (size_t k = 0; k < blocks; ++k) {
    for (size_t i = 0; i < block_links[k].size(); ++i) {
      const NeighborPair& pr = candidates_[block_links[k][i]];
      if (!c_.all_links) {
        int ra = joined.find_set(pr.a), rb = joined.find_set(pr.b);
        if (ra == rb) continue;
        joined.link(ra, rb);
      }
      out_.certified_links.push_back(int32_t(out_.neighbors.size()));
      out_.neighbors.push_back(pr);
      if (c_.keep_link_proofs) out_.link_proofs.append_one(block_proofs[k], i);
    }
  }
  first_ += count;
}

}  // namespace aspects
