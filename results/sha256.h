// SHA-256 as 64 lowercase hex digits: the hashes that tie a result directory's files to
// one another (the model's, the certificate's, the index's own).
#pragma once

#include <cstddef>
#include <string>

namespace aspects {

// Fed in pieces (an index of a gigabyte is hashed as it is written or read).
class Sha256Hasher {
 public:
  Sha256Hasher();
  ~Sha256Hasher();
  Sha256Hasher(const Sha256Hasher&) = delete;
  Sha256Hasher& operator=(const Sha256Hasher&) = delete;
  void update(const void* data, size_t n);
  std::string hex();  // the hash of every byte so far; call once
  std::string raw();  // the same as 32 bytes; call once (instead of hex)
  std::string peek_raw() const;  // the hash so far, 32 bytes; more may be fed after

 private:
  void* ctx_;
};

std::string sha256_hex_of(const std::string& bytes);
std::string hex_of(const std::string& raw);  // lowercase, two digits a byte

}  // namespace aspects
