#include "run/search_part_codec.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace aspects {

namespace {

constexpr uint8_t kLeaf = 0x40, kHasIndex = 0x08, kHasReason = 0x10, kExtras = 0x20;

uint64_t bits_of(double d) {
  uint64_t v;
  std::memcpy(&v, &d, 8);
  return v;
}
double double_of(uint64_t v) {
  double d;
  std::memcpy(&d, &v, 8);
  return d;
}
uint64_t zigzag(int64_t v) { return (uint64_t(v) << 1) ^ uint64_t(v >> 63); }
int64_t unzigzag(uint64_t u) { return int64_t(u >> 1) ^ -int64_t(u & 1); }

// The part's bytes, gathered in one string: the owner's writer is called once a part.
class Out {
 public:
  void u8(uint8_t v) { s.push_back(char(v)); }
  void varint(uint64_t v) {
    for (; v >= 0x80; v >>= 7) s.push_back(char(v | 0x80));
    s.push_back(char(v));
  }
  void f64(double d) { raw(bits_of(d), 0, 8); }
  // x's bytes between its zero bytes at either end.
  void xored(uint64_t x) {
    if (x == 0) return u8(0x80);
    const int lead = __builtin_clzll(x) / 8, trail = __builtin_ctzll(x) / 8;
    u8(uint8_t(lead << 4 | trail));
    raw(x, trail, 8 - lead);
  }
  std::string s;

 private:
  void raw(uint64_t v, int from, int to) {
    for (int i = from; i < to; ++i) s.push_back(char((v >> (8 * i)) & 0xffu));
  }
};

// Bytes of one part, in place; a failure is the owner's (LeReader::fail).
class In {
 public:
  In(std::string_view b, const LeReader& owner) : p_(b.data()), end_(p_ + b.size()),
                                                  owner_(owner) {}
  [[noreturn]] void fail(const std::string& why) const {
    owner_.fail(why + " in a part");
    std::abort();  // not reached: the owner's fail throws (GCC does not see it)
  }
  bool at_end() const { return p_ == end_; }
  size_t left() const { return size_t(end_ - p_); }
  uint8_t u8() {
    if (p_ == end_) fail("truncated");
    return uint8_t(*p_++);
  }
  uint64_t varint() {
    uint64_t v = 0;
    for (int shift = 0;; shift += 7) {
      const uint8_t b = u8();
      if (shift == 63 && b > 1) fail("bad varint");
      v |= uint64_t(b & 0x7f) << shift;
      if (!(b & 0x80)) return v;
    }
  }
  int64_t signed_varint() { return unzigzag(varint()); }
  double f64() { return double_of(raw(0, 8)); }
  uint64_t xored() {
    const uint8_t h = u8();
    if (h == 0x80) return 0;
    const int lead = h >> 4, trail = h & 0x0f;
    if (lead + trail > 7) fail("bad end");
    return raw(trail, 8 - lead);
  }

 private:
  uint64_t raw(int from, int to) {
    if (left() < size_t(to - from)) fail("truncated");
    uint64_t v = 0;
    for (int i = from; i < to; ++i) v |= uint64_t(uint8_t(*p_++)) << (8 * i);
    return v;
  }
  const char* p_;
  const char* end_;
  const LeReader& owner_;
};

void write_tree(Out& o, const std::vector<SearchNode>& tree) {
  o.varint(tree.size());
  if (tree.empty()) return;
  std::vector<int32_t> stack{0};
  int32_t next_left = 1, next_box = 0, next_deferred = 0;
  while (!stack.empty()) {
    const SearchNode& s = tree[size_t(stack.back())];
    stack.pop_back();
    const bool extras = s.fate != LeafFate::Discarded || s.reason != -1;
    if (s.internal()) {
      if (s.left() != next_left || s.split_var >= 32)
        throw std::logic_error("write_search_part: a tree not in the search's order");
      next_left += 2;
      o.u8(uint8_t(s.split_var | (extras ? kExtras : 0)));
      o.f64(s.split);
      if (extras) {
        o.u8(uint8_t(s.fate));
        o.varint(zigzag(s.reason));
      }
      stack.push_back(s.right());
      stack.push_back(s.left());
      continue;
    }
    int32_t& next = s.fate == LeafFate::Deferred ? next_deferred : next_box;
    o.u8(uint8_t(kLeaf | uint8_t(s.fate) | (s.index != -1 ? kHasIndex : 0) |
                 (s.reason != -1 ? kHasReason : 0)));
    if (s.index != -1) {
      o.varint(zigzag(int64_t(s.index) - next));
      next = s.index + 1;
    }
    if (s.reason != -1) o.varint(zigzag(s.reason));
  }
}

void read_tree(In& in, std::vector<SearchNode>& tree, uint32_t nv) {
  const uint64_t nodes = in.varint();
  if (nodes > in.left() || nodes > uint64_t(INT32_MAX)) in.fail("bad node count");
  tree.assign(size_t(nodes), SearchNode());
  if (nodes == 0) return;
  auto fate_of = [&](uint8_t f) {
    if (f > uint8_t(LeafFate::Unexplored)) in.fail("bad leaf fate");
    return LeafFate(f);
  };
  auto reason = [&] {
    const int64_t r = in.signed_varint();
    if (r < -1 || r > kMaxPruneReason) in.fail("bad prune reason");
    return int16_t(r);
  };
  std::vector<int32_t> stack{0};
  int64_t next_left = 1, next_box = 0, next_deferred = 0;
  while (!stack.empty()) {
    SearchNode& s = tree[size_t(stack.back())];
    stack.pop_back();
    const uint8_t c = in.u8();
    if (!(c & kLeaf)) {
      const int var = c & 0x1f;
      if ((c & 0x80) || uint32_t(var) >= nv || next_left + 1 >= int64_t(nodes))
        in.fail("bad tree node");
      const double split = in.f64();
      s.set_children(var, split, int32_t(next_left));
      if (c & kExtras) {
        s.fate = fate_of(in.u8());
        s.reason = reason();
      }
      stack.push_back(int32_t(next_left + 1));
      stack.push_back(int32_t(next_left));
      next_left += 2;
      continue;
    }
    if (c & 0xa0) in.fail("bad tree node");
    s.fate = fate_of(c & 0x07);
    if (c & kHasIndex) {
      int64_t& next = s.fate == LeafFate::Deferred ? next_deferred : next_box;
      const int64_t index = next + in.signed_varint();
      if (index < 0 || index > INT32_MAX) in.fail("bad leaf index");
      s.index = int32_t(index);
      next = index + 1;
    }
    if (c & kHasReason) s.reason = reason();
  }
  if (next_left != int64_t(nodes)) in.fail("bad tree (nodes left over)");
}

}  // namespace

void write_search_part(LeWriter& out, const SearchPart& part, uint32_t p) {
  Out o;
  write_tree(o, part.tree);
  const OutputBoxes& r = part.boxes;
  const size_t boxes = size_t(r.size());
  o.varint(boxes);
  const std::vector<double>& ends = r.ends().coords();
  const size_t width = ends.size() / std::max<size_t>(1, boxes);
  for (size_t i = 0; i < ends.size(); ++i) {
    const uint64_t before = i >= width ? bits_of(ends[i - width]) : 0;
    o.xored(bits_of(ends[i]) ^ before);
  }
  for (size_t b = 0; b < boxes; ++b)
    o.u8(uint8_t(uint8_t(r.certified(int(b))) | uint8_t(r.kind(int(b))) << 1));
  const std::vector<int8_t>& signs = r.sign_column();
  if (signs.size() != boxes * p) throw std::logic_error("write_search_part: not p signs a box");
  for (size_t i = 0; i < signs.size(); i += 4) {
    uint8_t packed = 0;
    for (size_t j = i; j < std::min(signs.size(), i + 4); ++j) {
      if (signs[j] < -1 || signs[j] > 1)
        throw std::logic_error("write_search_part: a sign not -1, 0, +1");
      packed |= uint8_t(signs[j] + 1) << (2 * (j - i));
    }
    o.u8(packed);
  }
  const SearchDiagnostics& d = part.diagnostics;
  for (int k = 0; k < kVerdicts; ++k) o.varint(zigzag(d.attempts[k]));
  for (int k = 0; k < kVerdicts; ++k) o.varint(zigzag(d.undecided[k]));
  for (long x : {d.refuted_by_equation, d.refuted_by_newton, d.refuted_by_constraint})
    o.varint(zigzag(x));
  out.u64(o.s.size());
  out.bytes(o.s.data(), o.s.size());
}

void read_search_part(LeReader& owner, SearchPart& part, uint32_t nv, uint32_t p,
                      uint32_t deferred) {
  In in(owner.view(owner.u64()), owner);
  read_tree(in, part.tree, nv);
  const uint64_t boxes = in.varint();
  // Each box takes at least a byte an end and its flags.
  if (boxes > in.left() / (2 * uint64_t(nv) + 1)) in.fail("bad box count");
  std::vector<double> coords(size_t(boxes) * 2 * nv);
  const size_t width = 2 * size_t(nv);
  std::vector<uint64_t> prev(width, 0);
  for (size_t i = 0; i < coords.size(); ++i) {
    uint64_t& last = prev[i % width];
    last ^= in.xored();
    coords[i] = double_of(last);
  }
  std::vector<uint8_t> certified(boxes);
  std::vector<UndecidedKind> kinds(boxes);
  for (size_t b = 0; b < boxes; ++b) {
    const uint8_t f = in.u8();
    if (f >> 1 > uint8_t(UndecidedKind::Unexplored)) in.fail("bad undecided kind");
    certified[b] = f & 1;
    kinds[b] = UndecidedKind(f >> 1);
  }
  std::vector<int8_t> signs(size_t(boxes) * p);
  for (size_t i = 0; i < signs.size(); i += 4) {
    const uint8_t packed = in.u8();
    for (size_t j = i; j < std::min(signs.size(), i + 4); ++j) {
      const int code = (packed >> (2 * (j - i))) & 3;
      if (code == 3) in.fail("bad sign");
      signs[j] = int8_t(code - 1);
    }
  }
  part.boxes = OutputBoxes::from_columns(int(nv), int(p), coords, std::move(certified),
                                         std::move(kinds), std::move(signs));
  SearchDiagnostics& d = part.diagnostics;
  for (int k = 0; k < kVerdicts; ++k) d.attempts[k] = long(in.signed_varint());
  for (int k = 0; k < kVerdicts; ++k) d.undecided[k] = long(in.signed_varint());
  for (long* x : {&d.refuted_by_equation, &d.refuted_by_newton, &d.refuted_by_constraint})
    *x = long(in.signed_varint());
  if (!in.at_end()) in.fail("trailing bytes");
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
