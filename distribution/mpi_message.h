// The bytes of an MPI message (distribution/mpi_job.h), written and read with the little-endian
// fields of le_writer.h and le_reader.h.
#pragma once

#include <stdexcept>
#include <string>

#include "io/le_reader.h"
#include "io/le_writer.h"

namespace aspects {

class MessageWriter : public LeWriter {
 public:
  void bytes(const void* p, size_t n) override { s.append(static_cast<const char*>(p), n); }
  void str(const std::string& t) {
    u64(t.size());
    bytes(t.data(), t.size());
  }
  std::string s;
};

// A message that cannot be read names its sender: a rank of another build, or a bug.
class MessageReader : public LeReader {
 public:
  MessageReader(const std::string& b, int sender) : LeReader(b, b.size()), sender_(sender) {}
  [[noreturn]] void fail(const std::string& why) const override {
    throw std::runtime_error("MPI: a malformed message from rank " + std::to_string(sender_) +
                             " (" + why + " at byte " + std::to_string(pos()) + ")");
  }
  std::string str() { return bytes(u64()); }

 private:
  int sender_;
};

}  // namespace aspects
