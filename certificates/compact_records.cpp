#include "compact_records.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "certificate_grid.h"

namespace aspects {

namespace compact {

void varint(std::string& out, uint64_t x) {
  while (x >= 0x80) {
    out += char(0x80 | (x & 0x7f));
    x >>= 7;
  }
  out += char(x);
}

void u64(std::string& out, uint64_t x) {
  for (int i = 0; i < 8; ++i) out += char((x >> (8 * i)) & 0xff);
}

void raw(std::string& out, double x) {
  uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  u64(out, b);
}

std::vector<double> ends(const Box& box) {
  std::vector<double> out;
  for (const Interval& x : box) out.insert(out.end(), {x.lo_down(), x.hi_up()});
  return out;
}

void end(std::string& out, double x, double a, double b, double r, int64_t offset, int bits) {
  int64_t z;
  // The checker's step is (b − a)·2^-bits whatever step() says of it: it must be finite.
  const bool finite = std::isfinite(std::ldexp(b - a, -bits));
  if (finite && grid::code(x, r, grid::step(a, b, bits), z)) {
    const int64_t d = z - offset;
    varint(out, 1 + (d >= 0 ? 2 * uint64_t(d) : 2 * uint64_t(-(d + 1)) + 1));  // zigzag
  } else {
    out += char(0);
    raw(out, x);
  }
}

void signs(std::string& out, const char* s, int p) {
  for (int i = 0; i < p; i += 4) {
    unsigned byte = 0;
    for (int k = 0; k < 4 && i + k < p; ++k)
      byte |= unsigned(s[i + k] == '+' ? 1 : s[i + k] == '-' ? 2 : 0) << (2 * k);
    out += char(byte);
  }
}

}  // namespace compact

namespace {

// A variable in the tag of P and B records: 0..30 in the tag itself, else 31 then the rest.
void tagged(std::string& out, int base, int v) {
  out += char(base + (v < 31 ? v : 31));
  if (v >= 31) compact::varint(out, uint64_t(v - 31));
}

// Two bits a factor, as compact::signs codes "+-0".
void packed_signs(std::string& out, const int8_t* s, int p) {
  std::string chars(size_t(p), '0');
  for (int i = 0; i < p; ++i) chars[i] = s[i] > 0 ? '+' : s[i] < 0 ? '-' : '0';
  compact::signs(out, chars.c_str(), p);
}

}  // namespace

CompactTree::CompactTree(std::vector<double> root, std::vector<int> command, int factors)
    : stack_{std::move(root)}, command_(std::move(command)), p_(factors) {}

CompactTree::Cell& CompactTree::current() {
  if (!open_) {
    if (stack_.empty()) throw std::logic_error("format 3: a tree record after the last cell");
    cell_ = std::move(stack_.back());
    stack_.pop_back();
    open_ = true;
  }
  return cell_;
}

void CompactTree::end(std::string& out, double x, const double* ref, bool upper, int64_t offset,
                      int bits) {
  compact::end(out, x, ref[0], ref[1], ref[upper], offset, bits);
}

void CompactTree::contraction(int v, double lo, double hi, std::string& out) {
  Cell& cell = current();
  tagged(out, 0x80, v);
  end(out, lo, &cell[2 * v], false, 0, grid::kContractionBits);
  end(out, hi, &cell[2 * v], true, 0, grid::kContractionBits);
  cell[2 * v] = lo;
  cell[2 * v + 1] = hi;
}

void CompactTree::split(int v, double at, std::string& out) {
  Cell& cell = current();
  open_ = false;
  tagged(out, 0xA0, v);
  end(out, at, &cell[2 * v], false, int64_t(1) << (grid::kBits - 1));  // the middle is 0
  Cell right = cell;
  right[2 * v] = at;
  cell[2 * v + 1] = at;
  stack_.push_back(std::move(right));
  stack_.push_back(std::move(cell));
}

void CompactTree::discard(const char* hint, std::string& out) {
  current();
  open_ = false;
  out += char(0xC0);
  const std::string h(hint);
  const bool eq = h.compare(0, 2, "eq") == 0;
  const uint64_t i = h == "hs" ? 0 : std::strtoul(h.c_str() + (eq ? 2 : 1), nullptr, 10);
  compact::varint(out, h == "hs" ? 0 : eq ? 1 + 2 * i : 2 + 2 * i);
}

void CompactTree::leaf(bool unexplored, const int8_t* signs, std::string& out) {
  current();
  open_ = false;
  out += char(unexplored ? 0xC2 : 0xC1);  // the id is implied
  packed_signs(out, signs, p_);
}

void CompactTree::solution(const int8_t* signs, const std::vector<double>& Q,
                           const std::vector<double>& image, const std::vector<double>& weights,
                           std::string& out) {
  const Cell& cell = current();
  open_ = false;
  out += char(0xC3);
  packed_signs(out, signs, p_);
  const size_t n = command_.size();
  for (size_t j = 0; j < n; ++j) {
    end(out, Q[2 * j], &cell[2 * command_[j]], false);
    end(out, Q[2 * j + 1], &cell[2 * command_[j]], true);
  }
  for (size_t j = 0; j < n; ++j) {
    end(out, image[2 * j], &Q[2 * j], false);
    end(out, image[2 * j + 1], &Q[2 * j], true);
  }
  // The preconditioners are left out: the checker computes its own.
  const double one_two[2] = {1.0, 2.0};
  for (double w : weights) end(out, w, one_two, false);  // DX, DQ on the grid of [1, 2]
}

void CompactTree::deferred() {
  current();  // the subtree's records, written elsewhere, start from this cell
  open_ = false;
}

}  // namespace aspects
