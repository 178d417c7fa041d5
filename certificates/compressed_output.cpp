#include "compressed_output.h"

#include <sys/types.h>
#include <zstd.h>

#include <cerrno>
#include <vector>

namespace aspects {

namespace {

struct Compressor {
  FILE* raw = nullptr;
  ZSTD_CCtx* cctx = nullptr;
  std::vector<char> out = std::vector<char>(ZSTD_CStreamOutSize());
  bool failed = false;
};

// Runs the compressor on `in` with `mode`, writing what it produces; false on any error.
bool pump(Compressor& z, ZSTD_inBuffer& in, ZSTD_EndDirective mode) {
  for (;;) {
    ZSTD_outBuffer o{z.out.data(), z.out.size(), 0};
    const size_t left = ZSTD_compressStream2(z.cctx, &o, &in, mode);
    if (ZSTD_isError(left)) {
      errno = EIO;
      return false;
    }
    if (o.pos && std::fwrite(z.out.data(), 1, o.pos, z.raw) != o.pos) return false;
    // continue: done once the input is consumed; end: once the frame is wholly written.
    if (mode == ZSTD_e_continue ? in.pos == in.size : left == 0) return true;
  }
}

ssize_t write_compressed(void* cookie, const char* data, size_t n) {
  Compressor& z = *static_cast<Compressor*>(cookie);
  ZSTD_inBuffer in{data, n, 0};
  if (z.failed || !pump(z, in, ZSTD_e_continue)) {
    z.failed = true;
    return 0;  // fopencookie: 0 is the error return
  }
  return ssize_t(n);
}

int close_compressed(void* cookie) {
  Compressor* z = static_cast<Compressor*>(cookie);
  ZSTD_inBuffer none{nullptr, 0, 0};
  const bool ok = !z->failed && pump(*z, none, ZSTD_e_end);
  const int err = ok ? 0 : (errno ? errno : EIO);
  ZSTD_freeCCtx(z->cctx);
  delete z;
  if (ok) return 0;
  errno = err;
  return EOF;
}

}  // namespace

FILE* open_compressed_output(FILE* raw, int level, int workers) {
  auto* z = new Compressor;
  z->raw = raw;
  z->cctx = ZSTD_createCCtx();
  // With the frame's checksum a damaged file is refused when read, not read as other text.
  bool ok = z->cctx &&
            !ZSTD_isError(ZSTD_CCtx_setParameter(z->cctx, ZSTD_c_compressionLevel, level)) &&
            !ZSTD_isError(ZSTD_CCtx_setParameter(z->cctx, ZSTD_c_checksumFlag, 1));
  // A libzstd built without threads refuses workers: compress on the writer's thread then.
  if (ok && workers > 0) ZSTD_CCtx_setParameter(z->cctx, ZSTD_c_nbWorkers, workers);
  cookie_io_functions_t io{nullptr, write_compressed, nullptr, close_compressed};
  FILE* f = ok ? fopencookie(z, "w", io) : nullptr;
  if (!f) {
    ZSTD_freeCCtx(z->cctx);
    delete z;
    errno = errno ? errno : ENOMEM;
  }
  return f;
}

}  // namespace aspects
