// Little-endian fields written as bytes, the twin of le_reader.h: the encoding shared by
// the result index (aspects.idx) and the checkpoint. The owner says where the bytes go.
#pragma once

#include <cstdint>
#include <cstring>

namespace aspects {

class LeWriter {
 public:
  virtual ~LeWriter() = default;
  virtual void bytes(const void* p, size_t n) = 0;

  void u64(uint64_t v) {
    unsigned char b[8];
    for (int i = 0; i < 8; ++i) b[i] = (v >> (8 * i)) & 0xffu;
    bytes(b, 8);
  }
  void u32(uint32_t v) {
    unsigned char b[4];
    for (int i = 0; i < 4; ++i) b[i] = (v >> (8 * i)) & 0xffu;
    bytes(b, 4);
  }
  void u8(uint8_t v) { bytes(&v, 1); }
  void i32(int32_t v) { u32(uint32_t(v)); }
  void i64(int64_t v) { u64(uint64_t(v)); }
  void f64(double d) {
    uint64_t v;
    std::memcpy(&v, &d, 8);
    u64(v);
  }
};

}  // namespace aspects
