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

void raw(std::string& out, double x) {
  uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  for (int i = 0; i < 8; ++i) out += char((b >> (8 * i)) & 0xff);
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

// The fields of a text record, as strtod and strtol read them (the writer's own text).
struct Fields {
  explicit Fields(const std::string& line) {
    size_t start = 0;
    while (start <= line.size()) {
      size_t sp = line.find(' ', start);
      if (sp == std::string::npos) sp = line.size();
      f.push_back(line.substr(start, sp - start));
      start = sp + 1;
    }
  }
  double real(size_t i) const { return std::strtod(f.at(i).c_str(), nullptr); }
  long integer(size_t i) const { return std::strtol(f.at(i).c_str(), nullptr, 10); }
  std::vector<std::string> f;
};

// A variable in the tag of P and B records: 0..30 in the tag itself, else 31 then the rest.
void tagged(std::string& out, int base, long v) {
  out += char(base + (v < 31 ? v : 31));
  if (v >= 31) compact::varint(out, uint64_t(v - 31));
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
  const size_t before = out.size();
  compact::end(out, x, ref[0], ref[1], ref[upper], offset, bits);
  ++ends;
  raw_ends += out[before] == 0;
}

void CompactTree::record(const std::string& line, std::string& out) {
  const Fields r(line);
  const std::string& kind = r.f[0];
  Cell& cell = current();
  if (kind == "P") {
    const long v = r.integer(1);
    const double lo = r.real(2), hi = r.real(3);
    tagged(out, 0x80, v);
    end(out, lo, &cell[2 * v], false, 0, grid::kContractionBits);
    end(out, hi, &cell[2 * v], true, 0, grid::kContractionBits);
    cell[2 * v] = lo;
    cell[2 * v + 1] = hi;
    return;
  }
  open_ = false;
  if (kind == "B") {
    const long v = r.integer(1);
    const double x = r.real(2);
    tagged(out, 0xA0, v);
    end(out, x, &cell[2 * v], false, int64_t(1) << (grid::kBits - 1));  // the middle is 0
    Cell right = cell;
    right[2 * v] = x;
    cell[2 * v + 1] = x;
    stack_.push_back(std::move(right));
    stack_.push_back(std::move(cell));
    return;
  }
  if (kind == "X") {
    const std::string& h = r.f[1];
    out += char(0xC0);
    const bool eq = h.compare(0, 2, "eq") == 0;
    const long i = h == "hs" ? -1 : std::strtol(h.c_str() + (eq ? 2 : 1), nullptr, 10);
    compact::varint(out, h == "hs" ? 0 : eq ? 1 + 2 * uint64_t(i) : 2 + 2 * uint64_t(i));
    return;
  }
  const long id = r.integer(1);
  if (id != next_id_) throw std::logic_error("format 3: output ids out of order");
  ++next_id_;
  out += char(kind == "U" ? 0xC1 : kind == "N" ? 0xC2 : 0xC3);  // the id is implied
  compact::signs(out, r.f[2].c_str(), p_);
  if (kind != "S") return;
  const int n = int(command_.size());
  size_t k = 3;
  std::vector<double> Q(2 * n);
  for (int j = 0; j < n; ++j, k += 2) {
    Q[2 * j] = r.real(k);
    Q[2 * j + 1] = r.real(k + 1);
    end(out, Q[2 * j], &cell[2 * command_[j]], false);
    end(out, Q[2 * j + 1], &cell[2 * command_[j]], true);
  }
  for (int j = 0; j < n; ++j, k += 2) {
    end(out, r.real(k), &Q[2 * j], false);
    end(out, r.real(k + 1), &Q[2 * j], true);
  }
  k += 3 * size_t(n) * n;  // the preconditioners: the checker computes its own
  for (int j = 0; j < 2 * n; ++j, ++k) {  // DX, DQ on the grid of [1, 2]
    const double one_two[2] = {1.0, 2.0};
    end(out, r.real(k), one_two, false);
  }
}

}  // namespace aspects
