// Little-endian fields read from bytes [0, end) of a string, each bounds-checked: the
// decoding shared by the result index (aspects.idx) and the checkpoint. The owner says how
// a failure is reported: fail() throws the owner's error, naming the byte it stopped at.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace aspects {

class LeReader {
 public:
  LeReader(const std::string& b, size_t end) : b_(b), end_(end) {}
  virtual ~LeReader() = default;
  [[noreturn]] virtual void fail(const std::string& why) const = 0;

  size_t pos() const { return pos_; }
  size_t left() const { return end_ - pos_; }
  bool at_end() const { return pos_ == end_; }
  void need(uint64_t n) const {
    if (left() < n) fail("truncated");
  }
  uint64_t u64() { return uint64_t(take(8)); }
  uint32_t u32() { return uint32_t(take(4)); }
  uint8_t u8() { return uint8_t(take(1)); }
  int32_t i32() { return int32_t(u32()); }
  int64_t i64() { return int64_t(u64()); }
  // The double with these bits (any, NaN included: the caller decides what it accepts).
  double f64_bits() {
    uint64_t v = u64();
    double d;
    std::memcpy(&d, &v, 8);
    return d;
  }
  // A count of records of at least `record_bytes` each, checked against the bytes left
  // before the caller allocates anything for them.
  uint32_t count(uint64_t record_bytes) {
    uint32_t c = u32();
    if (uint64_t(c) * record_bytes > left()) fail("truncated (a count is larger than the file)");
    return c;
  }
  // Skips the bytes of `s` when they come next; false (nothing read) otherwise.
  bool literal(const char* s) {
    size_t n = std::strlen(s);
    if (left() < n || b_.compare(pos_, n, s) != 0) return false;
    pos_ += n;
    return true;
  }
  // The next n bytes, in place (valid while the string read is).
  std::string_view view(uint64_t n) {
    need(n);
    std::string_view v(b_.data() + pos_, n);
    pos_ += n;
    return v;
  }
  // n bytes as a string (n already bounded by the caller).
  std::string bytes(uint64_t n) {
    need(n);
    std::string s = b_.substr(pos_, n);
    pos_ += n;
    return s;
  }

 private:
  uint64_t take(int n) {
    need(uint64_t(n));
    uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= uint64_t(uint8_t(b_[pos_ + i])) << (8 * i);
    pos_ += n;
    return v;
  }
  const std::string& b_;
  size_t end_;
  size_t pos_ = 0;
};

}  // namespace aspects
