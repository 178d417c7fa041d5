#include "hashing_output.h"

#include <openssl/evp.h>
#include <sys/types.h>

#include <cerrno>

namespace aspects {

namespace {

struct Hashing {
  FILE* next = nullptr;
  EVP_MD_CTX* md = nullptr;
  std::string* hex = nullptr;
  bool failed = false;
};

ssize_t write_hashing(void* cookie, const char* data, size_t n) {
  Hashing& h = *static_cast<Hashing*>(cookie);
  if (h.failed || EVP_DigestUpdate(h.md, data, n) != 1 || std::fwrite(data, 1, n, h.next) != n) {
    h.failed = true;
    if (!errno) errno = EIO;
    return 0;  // fopencookie: 0 is the error return
  }
  return ssize_t(n);
}

int close_hashing(void* cookie) {
  Hashing* h = static_cast<Hashing*>(cookie);
  unsigned char d[EVP_MAX_MD_SIZE];
  unsigned len = 0;
  const bool ok = !h->failed && EVP_DigestFinal_ex(h->md, d, &len) == 1;
  if (ok) {
    static const char* x = "0123456789abcdef";
    h->hex->clear();
    for (unsigned i = 0; i < len; ++i) {
      *h->hex += x[d[i] >> 4];
      *h->hex += x[d[i] & 15];
    }
  }
  const int err = ok ? 0 : (errno ? errno : EIO);
  EVP_MD_CTX_free(h->md);
  delete h;
  if (ok) return 0;
  errno = err;
  return EOF;
}

}  // namespace

FILE* open_hashing_output(FILE* next, std::string* hex) {
  auto* h = new Hashing;
  h->next = next;
  h->hex = hex;
  h->md = EVP_MD_CTX_new();
  const bool ok = h->md && EVP_DigestInit_ex(h->md, EVP_sha256(), nullptr) == 1;
  cookie_io_functions_t io{nullptr, write_hashing, nullptr, close_hashing};
  FILE* f = ok ? fopencookie(h, "w", io) : nullptr;
  if (!f) {
    EVP_MD_CTX_free(h->md);
    delete h;
    errno = errno ? errno : ENOMEM;
  }
  return f;
}

}  // namespace aspects
