#include "search_part_codec.h"

#include <vector>

namespace aspects {

void write_search_part(LeWriter& o, const SearchPart& part, uint32_t p) {
  o.u32(uint32_t(part.tree.size()));
  // The format's node, whatever SearchNode's packing: left and right child (-1 for a
  // leaf), split variable, split point, leaf index (-1 for an internal node).
  for (const SearchNode& s : part.tree) {
    o.i32(s.internal() ? s.left() : -1);
    o.i32(s.internal() ? s.right() : -1);
    o.i32(s.split_var);
    o.f64(s.split);
    o.i32(s.leaf());
    o.u8(uint8_t(s.fate));
    o.i32(s.reason);
  }
  const OutputBoxes& r = part.boxes;
  const uint32_t boxes = uint32_t(r.size());
  o.u32(boxes);
  for (double x : r.ends().coords()) o.f64(x);
  for (uint32_t b = 0; b < boxes; ++b) o.u8(r.certified(b));
  for (uint32_t b = 0; b < boxes; ++b) o.u8(uint8_t(r.kind(b)));
  for (size_t i = 0; i < size_t(boxes) * p; ++i) o.u8(uint8_t(r.sign_column()[i]));
  const SearchDiagnostics& d = part.diagnostics;
  for (int k = 0; k < kVerdicts; ++k) o.i64(d.attempts[k]);
  for (int k = 0; k < kVerdicts; ++k) o.i64(d.undecided[k]);
  for (long x : {d.refuted_by_equation, d.refuted_by_newton, d.refuted_by_constraint})
    o.i64(x);
}

void read_search_part(LeReader& in, SearchPart& part, uint32_t nv, uint32_t p,
                      uint32_t deferred) {
  const uint32_t nodes = in.count(29);
  part.tree.resize(nodes);
  for (SearchNode& s : part.tree) {
    const int32_t left = in.i32(), right = in.i32(), var = in.i32();
    s.split = in.f64_bits();
    const int32_t leaf = in.i32();
    uint8_t fate = in.u8();
    if (fate > uint8_t(LeafFate::Unexplored)) in.fail("bad leaf fate");
    s.fate = LeafFate(fate);
    const int32_t reason = in.i32();
    if (reason < -1 || reason > kMaxPruneReason) in.fail("bad prune reason");
    s.reason = int16_t(reason);
    if (var >= 0) {
      // Children adjacent and in range, the variable the model's.
      if (var >= int32_t(nv) || left <= 0 || right != left + 1 || right >= int32_t(nodes))
        in.fail("bad tree node");
      s.set_children(var, s.split, left);
    } else {
      s.index = leaf;
    }
  }
  const uint32_t boxes = in.count(16 * uint64_t(nv) + 2 + p);
  std::vector<double> coords(size_t(boxes) * 2 * nv);
  for (double& x : coords) x = in.f64_bits();
  std::vector<uint8_t> certified(boxes);
  for (auto& c : certified) c = in.u8();
  std::vector<UndecidedKind> kinds(boxes);
  for (auto& k : kinds) {
    uint8_t v = in.u8();
    if (v > uint8_t(UndecidedKind::Unexplored)) in.fail("bad undecided kind");
    k = UndecidedKind(v);
  }
  std::vector<int8_t> signs(size_t(boxes) * p);
  for (auto& s : signs) s = int8_t(in.u8());
  part.boxes = OutputBoxes::from_columns(int(nv), int(p), coords, std::move(certified),
                                         std::move(kinds), std::move(signs));
  SearchDiagnostics& d = part.diagnostics;
  for (int k = 0; k < kVerdicts; ++k) d.attempts[k] = long(in.i64());
  for (int k = 0; k < kVerdicts; ++k) d.undecided[k] = long(in.i64());
  for (long* x : {&d.refuted_by_equation, &d.refuted_by_newton, &d.refuted_by_constraint})
    *x = long(in.i64());
  for (const SearchNode& s : part.tree) {
    if (s.internal()) continue;
    if (s.fate == LeafFate::Deferred) {
      if (s.index < 0 || uint32_t(s.index) >= deferred) in.fail("bad deferred subtree");
    } else if (s.index >= int32_t(boxes)) {
      in.fail("bad output box");
    }
  }
}

}  // namespace aspects
