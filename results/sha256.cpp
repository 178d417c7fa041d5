#include "results/sha256.h"

#include <openssl/evp.h>

#include <stdexcept>

namespace aspects {

Sha256Hasher::Sha256Hasher() : ctx_(EVP_MD_CTX_new()) {
  if (!ctx_ || EVP_DigestInit_ex(static_cast<EVP_MD_CTX*>(ctx_), EVP_sha256(), nullptr) != 1)
    throw std::runtime_error("SHA-256 is not available (OpenSSL)");
}

Sha256Hasher::~Sha256Hasher() { EVP_MD_CTX_free(static_cast<EVP_MD_CTX*>(ctx_)); }

void Sha256Hasher::update(const void* data, size_t n) {
  EVP_DigestUpdate(static_cast<EVP_MD_CTX*>(ctx_), data, n);
}

std::string Sha256Hasher::raw() {
  unsigned char d[EVP_MAX_MD_SIZE];
  unsigned len = 0;
  EVP_DigestFinal_ex(static_cast<EVP_MD_CTX*>(ctx_), d, &len);
  return std::string(reinterpret_cast<const char*>(d), len);
}

std::string Sha256Hasher::peek_raw() const {
  EVP_MD_CTX* copy = EVP_MD_CTX_new();
  unsigned char d[EVP_MAX_MD_SIZE];
  unsigned len = 0;
  if (!copy || EVP_MD_CTX_copy_ex(copy, static_cast<EVP_MD_CTX*>(ctx_)) != 1 ||
      EVP_DigestFinal_ex(copy, d, &len) != 1) {
    EVP_MD_CTX_free(copy);
    throw std::runtime_error("SHA-256 failed (OpenSSL)");
  }
  EVP_MD_CTX_free(copy);
  return std::string(reinterpret_cast<const char*>(d), len);
}

std::string Sha256Hasher::hex() { return hex_of(raw()); }

std::string hex_of(const std::string& raw) {
  static const char* x = "0123456789abcdef";
  std::string s;
  for (unsigned char c : raw) {
    s += x[c >> 4];
    s += x[c & 15];
  }
  return s;
}

std::string sha256_hex_of(const std::string& bytes) {
  Sha256Hasher h;
  h.update(bytes.data(), bytes.size());
  return h.hex();
}

}  // namespace aspects
