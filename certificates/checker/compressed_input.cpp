// compressed_input.cpp — trusted core: certificates compressed by zstd (`aspects solve
// --compress-cert`) are read through a FILE* that decompresses them, so that everything after this
// file sees the text, and the SHA-256 check_cert reports is the text's, compressed or not.
#include <zstd.h>

#include <cerrno>
#include <vector>

#include "checker.h"

namespace cc {

namespace {

struct Decompressor {
  FILE* raw = nullptr;
  ZSTD_DCtx* dctx = nullptr;
  std::vector<char> buf = std::vector<char>(ZSTD_DStreamInSize());
  ZSTD_inBuffer in{nullptr, 0, 0};
  size_t pending = 1;  // ZSTD_decompressStream's last hint: 0 once a frame is complete
};

ssize_t read_decompressed(void* cookie, char* data, size_t n) {
  Decompressor& z = *static_cast<Decompressor*>(cookie);
  ZSTD_outBuffer out{data, n, 0};
  while (out.pos == 0 && n > 0) {
    if (z.in.pos == z.in.size) {
      const size_t k = std::fread(z.buf.data(), 1, z.buf.size(), z.raw);
      if (k == 0) {
        // The end of the file: an error unless the last frame was complete.
        if (std::ferror(z.raw) || z.pending != 0) {
          errno = EIO;
          return -1;
        }
        return 0;
      }
      z.in = ZSTD_inBuffer{z.buf.data(), k, 0};
    }
    z.pending = ZSTD_decompressStream(z.dctx, &out, &z.in);
    if (ZSTD_isError(z.pending)) {
      errno = EIO;
      return -1;
    }
  }
  return ssize_t(out.pos);
}

int close_decompressed(void* cookie) {
  Decompressor* z = static_cast<Decompressor*>(cookie);
  const int r = std::fclose(z->raw);
  ZSTD_freeDCtx(z->dctx);
  delete z;
  return r;
}

}  // namespace

FILE* decompressed(FILE* f) {
  // A certificate's text starts with 'a'; a zstd frame with 0x28 (magic 0xFD2FB528, little
  // endian). One byte of push-back is all stdio guarantees, and all this needs.
  const int c = std::getc(f);
  if (c == EOF || std::ungetc(c, f) == EOF || c != 0x28) return f;
  auto* z = new Decompressor;
  z->raw = f;
  z->dctx = ZSTD_createDCtx();
  FILE* g = nullptr;
  if (z->dctx) {
    cookie_io_functions_t io{read_decompressed, nullptr, nullptr, close_decompressed};
    g = fopencookie(z, "r", io);
  }
  if (!g) {
    ZSTD_freeDCtx(z->dctx);
    delete z;
    return f;  // read as it is: rejected as not a certificate, with its first record
  }
  return g;
}

}  // namespace cc
