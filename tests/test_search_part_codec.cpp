// The part encoding of checkpoints and MPI messages (apps/search_part_codec.h): real parts
// of a stopped RPRPR search (a top with deferred leaves, finished and partial subtrees)
// come back field for field, and damaged bytes are refused, never read as another part.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

#include "generalized_aspects.h"
#include "model/determinant_factors.h"
#include "mpi_message.h"
#include "search/stop_condition.h"
#include "search_part_codec.h"

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

}  // namespace
}  // namespace aspects
