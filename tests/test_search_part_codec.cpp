// The part encoding of checkpoints and MPI messages (run/search_part_codec.h): real parts
// of a stopped RPRPR search (a top with deferred leaves, finished and partial subtrees)
// come back field for field, and damaged bytes are refused, never read as another part.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <utility>
#include <vector>

#include "deep_tree.h"
#include "distribution/mpi_message.h"
#include "generalized_aspects.h"
#include "model/determinant_factors.h"
#include "pipeline/part_merger.h"
#include "run/search_part_codec.h"
#include "search/stop_condition.h"

namespace aspects {
namespace {

std::string encode(const SearchPart& part, uint32_t p) {
  MessageWriter w;
  write_search_part(w, part, p);
  return w.s;
}

SearchPart decode(const std::string& bytes, uint32_t nv, uint32_t p, uint32_t deferred) {
  MessageReader in(bytes, 1);
  SearchPart part;
  read_search_part(in, part, nv, p, deferred);
  if (!in.at_end()) in.fail("trailing bytes");
  return part;
}

void expect_same(const SearchPart& a, const SearchPart& b) {
  ASSERT_EQ(a.tree.size(), b.tree.size());
  for (size_t i = 0; i < a.tree.size(); ++i) {
    const SearchNode &x = a.tree[i], &y = b.tree[i];
    ASSERT_EQ(std::memcmp(&x.split, &y.split, 8), 0) << "node " << i;
    ASSERT_EQ(x.index, y.index) << "node " << i;
    ASSERT_EQ(x.reason, y.reason) << "node " << i;
    ASSERT_EQ(x.split_var, y.split_var) << "node " << i;
    ASSERT_EQ(x.fate, y.fate) << "node " << i;
  }
  ASSERT_EQ(a.boxes.size(), b.boxes.size());
  const auto &ca = a.boxes.ends().coords(), &cb = b.boxes.ends().coords();
  ASSERT_EQ(ca.size(), cb.size());
  EXPECT_EQ(std::memcmp(ca.data(), cb.data(), ca.size() * sizeof(double)), 0);
  EXPECT_EQ(a.boxes.sign_column(), b.boxes.sign_column());
  for (int i = 0; i < a.boxes.size(); ++i) {
    ASSERT_EQ(a.boxes.certified(i), b.boxes.certified(i)) << "box " << i;
    ASSERT_EQ(a.boxes.kind(i), b.boxes.kind(i)) << "box " << i;
  }
  for (int k = 0; k < kVerdicts; ++k) {
    EXPECT_EQ(a.diagnostics.attempts[k], b.diagnostics.attempts[k]);
    EXPECT_EQ(a.diagnostics.undecided[k], b.diagnostics.undecided[k]);
  }
  EXPECT_EQ(a.diagnostics.refuted_by_equation, b.diagnostics.refuted_by_equation);
  EXPECT_EQ(a.diagnostics.refuted_by_newton, b.diagnostics.refuted_by_newton);
  EXPECT_EQ(a.diagnostics.refuted_by_constraint, b.diagnostics.refuted_by_constraint);
}

// The state of RPRPR's search stopped half way (as a checkpoint holds it).
struct Stopped {
  SearchState state;
  uint32_t nv = 0, p = 0;
};

const Stopped& stopped_rprpr() {
  static const Stopped s = [] {
    set_working_precision(53);
    Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rprpr.robot");
    Stopped out;
    out.nv = uint32_t(m.vars.size());
    out.p = uint32_t(determinant_factors(m).size());
    const long full = long(compute_aspects(m, AspectsConfig()).tree.size());
    Model m2 = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rprpr.robot");
    StopCondition stop;
    stop.set_max_boxes(full / 2);
    AspectsConfig cfg;
    cfg.stop = &stop;
    cfg.checkpoint_seconds = 1e9;  // only the write when the search stops
    cfg.checkpoint = [&](const SearchState& st, const std::vector<uint8_t>& done) {
      out.state.top = st.top;
      out.state.deferred = st.deferred;
      out.state.done = done;
      out.state.parts = st.parts;
    };
    compute_aspects(m2, cfg);
    return out;
  }();
  return s;
}

TEST(SearchPartCodec, RealPartsComeBackFieldForField) {
  const Stopped& s = stopped_rprpr();
  const uint32_t deferred = uint32_t(s.state.deferred.size());
  ASSERT_GT(deferred, 0u);
  const SearchPart& top = s.state.top;
  long deferred_leaves = 0;
  for (const SearchNode& n : top.tree) deferred_leaves += n.fate == LeafFate::Deferred;
  EXPECT_EQ(deferred_leaves, long(deferred));
  expect_same(top, decode(encode(top, s.p), s.nv, s.p, deferred));
  long parts = 0, unexplored = 0, boxes = 0, nodes = 0, bytes = 0;
  for (size_t k = 0; k < s.state.parts.size(); ++k) {
    if (s.state.parts[k].tree.empty()) continue;
    const SearchPart& part = s.state.parts[k];
    const std::string b = encode(part, s.p);
    ASSERT_NO_FATAL_FAILURE(expect_same(part, decode(b, s.nv, s.p, 0))) << "part " << k;
    ++parts;
    for (const SearchNode& n : part.tree) unexplored += n.fate == LeafFate::Unexplored;
    boxes += part.boxes.size();
    nodes += long(part.tree.size());
    bytes += long(b.size());
  }
  EXPECT_GT(parts, 10);
  EXPECT_GT(unexplored, 0);  // a subtree stopped half way
  EXPECT_GT(boxes, 0);
  // The point of the encoding: far below the 29 bytes a node and 16 nv + 2 + p a box of
  // fixed-width fields.
  EXPECT_LT(double(bytes), 0.6 * double(29 * nodes + (16 * s.nv + 2 + s.p) * boxes));
}

TEST(SearchPartCodec, DamagedBytesAreRefused) {
  const Stopped& s = stopped_rprpr();
  const SearchPart* part = nullptr;
  for (const SearchPart& p : s.state.parts)
    if (!p.tree.empty() && p.boxes.size() > 3 && (!part || p.tree.size() < part->tree.size()))
      part = &p;
  ASSERT_NE(part, nullptr);
  const std::string good = encode(*part, s.p);
  // Every shorter length, with its length field mended, is refused.
  for (size_t cut = 8; cut < good.size(); ++cut) {
    std::string b = good.substr(0, cut);
    const uint64_t n = cut - 8;
    for (int i = 0; i < 8; ++i) b[size_t(i)] = char((n >> (8 * i)) & 0xffu);
    EXPECT_THROW(decode(b, s.nv, s.p, 0), std::runtime_error) << "cut at " << cut;
  }
  EXPECT_THROW(decode(good + "x", s.nv, s.p, 0), std::runtime_error);  // after the part
  std::string longer = good + "x";
  longer[0] = char(uint8_t(longer[0]) + 1);  // a byte more inside the part
  EXPECT_THROW(decode(longer, s.nv, s.p, 0), std::runtime_error);
  // A model with fewer variables than the split variables named.
  EXPECT_THROW(decode(good, 1, s.p, 0), std::runtime_error);
  // The signs, two bits each, last: code 3 is no sign.
  std::string bad_sign = good;
  size_t sign_bytes = (size_t(part->boxes.size()) * s.p + 3) / 4;
  ASSERT_GT(sign_bytes, 0u);
  // The diagnostics follow the signs: find the last sign byte by re-encoding without them.
  SearchPart no_diag = *part;
  no_diag.diagnostics = SearchDiagnostics();
  const size_t diag_bytes = encode(no_diag, s.p).size() - (2 * kVerdicts + 3);
  bad_sign[diag_bytes - 1] = char(0xff);
  EXPECT_THROW(decode(bad_sign, s.nv, s.p, 0), std::runtime_error);
}

TEST(SearchPartCodec, DeferredLeavesNameTheTopsSubtrees) {
  const Stopped& s = stopped_rprpr();
  const std::string b = encode(s.state.top, s.p);
  const uint32_t deferred = uint32_t(s.state.deferred.size());
  EXPECT_NO_THROW(decode(b, s.nv, s.p, deferred));
  EXPECT_THROW(decode(b, s.nv, s.p, deferred - 1), std::runtime_error);  // one too many
}

TEST(SearchPartCodec, ATreeNotInTheSearchsOrderIsNotWritten) {
  // Children swapped between two internal nodes: a tree the search cannot have made, which
  // the encoding (children implied by the order) could not give back.
  const Stopped& s = stopped_rprpr();
  SearchPart part = s.state.top;
  int first = -1, second = -1;
  for (int i = 0; i < int(part.tree.size()) && second < 0; ++i)
    if (part.tree[size_t(i)].internal()) (first < 0 ? first : second) = i;
  ASSERT_GE(second, 0);
  std::swap(part.tree[size_t(first)].index, part.tree[size_t(second)].index);
  EXPECT_THROW(encode(part, s.p), std::logic_error);
}

SearchPart part_of(DeepTree d) {
  SearchPart part;
  part.tree = std::move(d.tree);
  part.boxes = std::move(d.boxes);
  return part;
}

// Issue 50: a run stopped far down the tree. The coder and the decoder keep their own
// stacks, so a part 200,000 levels deep (tests/deep_tree.h) comes back whole.
TEST(SearchPartCodec, APartDeeperThanTheStackComesBack) {
  set_working_precision(53);
  const SearchPart part = part_of(deep_tree(kDeepTreeLevels, LeafFate::Unexplored, 2, 2, 3));
  ASSERT_EQ(part.tree.size(), 2 * size_t(kDeepTreeLevels) + 1);
  ASSERT_EQ(part.boxes.size(), 5);
  expect_same(part, decode(encode(part, 2), 2, 2, 0));
}

// The depth of the merged tree's deepest leaf (an explicit stack: the tree is deep).
size_t depth_of(const std::vector<SearchNode>& tree) {
  size_t deepest = 0;
  std::vector<std::pair<int32_t, size_t>> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [i, depth] = stack.back();
    stack.pop_back();
    deepest = std::max(deepest, depth);
    if (!tree[size_t(i)].internal()) continue;
    stack.push_back({tree[size_t(i)].right(), depth + 1});
    stack.push_back({tree[size_t(i)].left(), depth + 1});
  }
  return deepest;
}

// The merge grafts a deep subtree, come back encoded as from another rank, below a deep
// top's deferred leaf: one tree twice as deep, in the search's order, its boxes depth first
// (the subtree's, then the top's). Before issue 50 the graft recursed once a level and
// overflowed the stack (SIGSEGV).
TEST(SearchPartCodec, TheMergeGraftsPartsDeeperThanTheStack) {
  set_working_precision(53);
  const int levels = kDeepTreeLevels / 2;
  SearchPart top = part_of(deep_tree(levels, LeafFate::Deferred, 2, 2, 2));
  const SearchPart sub = part_of(deep_tree(levels, LeafFate::Unexplored, 2, 2));
  ASSERT_EQ(top.boxes.size(), 3);
  ASSERT_EQ(sub.boxes.size(), 2);
  const size_t nodes = top.tree.size() - 1 + sub.tree.size();
  std::vector<SearchPart> parts(1);
  std::vector<EncodedPart> encoded(1);
  encoded[0] = {encode(sub, 2), long(sub.tree.size()), long(sub.boxes.size())};
  SearchPart merged;
  merged.boxes = OutputBoxes(2, 2);
  int decoded = 0;
  PartMerger(parts, merged.boxes, merged.tree)
      .merge(top, &encoded, [&](int32_t k, const std::string& bytes, SearchPart& part) {
        EXPECT_EQ(k, 0);
        part = decode(bytes, 2, 2, 0);
        ++decoded;
      });
  EXPECT_EQ(decoded, 1);
  ASSERT_EQ(merged.tree.size(), nodes);
  EXPECT_EQ(depth_of(merged.tree), 2 * size_t(levels));
  // Boxes in depth-first order: the subtree's two (x from 0 and 1, the first unexplored),
  // then the top's three.
  ASSERT_EQ(merged.boxes.size(), 5);
  const double x_lo[] = {0, 1, 0, 1, 2};
  for (int b = 0; b < 5; ++b) EXPECT_EQ(merged.boxes.lo(b, 0), x_lo[b]) << "box " << b;
  EXPECT_TRUE(merged.boxes.unexplored(0));
  EXPECT_FALSE(merged.boxes.unexplored(2));
  // The graft numbered the merged tree as a search would have: the coder accepts it.
  EXPECT_NO_THROW(encode(merged, 2));
  EXPECT_TRUE(top.tree.empty());  // each part freed once grafted
  EXPECT_TRUE(parts[0].tree.empty());
  EXPECT_TRUE(encoded[0].bytes.empty());
}

}  // namespace
}  // namespace aspects
