#include "run/checkpoint.h"

#include <openssl/evp.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#include "certificate_writer.h"
#include "io/atomic_file.h"
#include "io/le_reader.h"
#include "io/le_writer.h"
#include "run/search_part_codec.h"

namespace aspects {

namespace {

// Layout (integers and doubles little-endian; a string is a u64 length and its bytes):
//   "aspects-checkpoint 2\n"  (1: parts in fixed-width fields)
//   str version  str model_sha256  str model_text  str model_file  f64 eps  f64 tau
//   i64 precision  str bisect  u8 all_links  u8 no_cert  u8 cert_format  i32 defer_depth
//   f64 checkpoint_seconds  u32 nv  u32 p
//   u8 top_done; when 1:
//     part(top)  str top_records  u32 M  M × (i64 offset  i32 task)   (format 3: where
//     each deferred subtree's records go in top_records; format 2 marks them in the text)
//     u32 D  D × (nv × (f64 lo  f64 hi)  i32 parent_split  i32 node)
//     D × (u8 done; when 1: part  str records)
//   32 bytes: SHA-256 of everything before
// part: run/search_part_codec.h
const char kMagic[] = "aspects-checkpoint 2\n";
constexpr size_t kDigest = 32;

class Sha256 {
 public:
  Sha256() : ctx_(EVP_MD_CTX_new()) { EVP_DigestInit_ex(ctx_, EVP_sha256(), nullptr); }
  ~Sha256() { EVP_MD_CTX_free(ctx_); }
  void add(const void* p, size_t n) { EVP_DigestUpdate(ctx_, p, n); }
  std::string digest() {
    unsigned char d[EVP_MAX_MD_SIZE];
    unsigned int len = 0;
    EVP_DigestFinal_ex(ctx_, d, &len);
    return std::string(reinterpret_cast<char*>(d), len);
  }

 private:
  EVP_MD_CTX* ctx_;
};

// Streams to a file while hashing, so a large state is never held twice in memory.
// The checkpoint's bytes, hashed as they go (the digest closes the file).
class Out : public LeWriter {
 public:
  explicit Out(AtomicFile& f) : f_(f) {}
  void bytes(const void* p, size_t n) override {
    sha_.add(p, n);
    f_.write(p, n);
  }
  void str(const std::string& s) {
    u64(s.size());
    bytes(s.data(), s.size());
  }
  void finish() { f_.write(sha_.digest()); }

 private:
  AtomicFile& f_;
  Sha256 sha_;
};

class In : public LeReader {
 public:
  In(const std::string& b, size_t end, const std::string& path) : LeReader(b, end), path_(path) {}
  [[noreturn]] void fail(const std::string& why) const override {
    throw CheckpointError(path_ + ": damaged checkpoint (" + why + " at byte " +
                          std::to_string(pos()) + "): refused, and left as it is");
  }
  double f64() { return f64_bits(); }
  std::string str() { return bytes(u64()); }

 private:
  std::string path_;
};

}  // namespace

std::string sha256_hex(const std::string& data) {
  Sha256 sha;
  sha.add(data.data(), data.size());
  std::string d = sha.digest(), s;
  static const char* hex = "0123456789abcdef";
  for (unsigned char c : d) {
    s += hex[c >> 4];
    s += hex[c & 15];
  }
  return s;
}

void write_checkpoint(const std::string& path, const CheckpointHeader& h, const SearchState& st,
                      const std::vector<uint8_t>& done, CertificateWriter* cert) {
  AtomicFile f(path);
  Out o(f);
  o.bytes(kMagic, std::strlen(kMagic));
  o.str(h.version);
  o.str(h.model_sha256);
  o.str(h.model_text);
  o.str(h.model_file);
  o.f64(h.eps);
  o.f64(h.tau);
  o.i64(h.precision);
  o.str(h.bisect);
  o.u8(h.all_links);
  o.u8(h.no_cert);
  o.u8(uint8_t(h.cert_format));
  o.i32(h.defer_depth);
  o.f64(h.checkpoint_seconds);
  o.u32(h.nv);
  o.u32(h.p);
  o.u8(st.top_done);
  if (st.top_done) {
    write_search_part(o, st.top, h.p);
    o.str(cert ? cert->records(-1) : std::string());
    const std::vector<TreeRecordFile::Mark> marks =
        cert ? cert->marks(-1) : std::vector<TreeRecordFile::Mark>();
    o.u32(uint32_t(marks.size()));
    for (const TreeRecordFile::Mark& m : marks) {
      o.i64(m.offset);
      o.i32(m.task);
    }
    o.u32(uint32_t(st.deferred.size()));
    for (const DeferredSubtree& d : st.deferred) {
      for (const Interval& x : d.box) {
        o.f64(x.lo_down());
        o.f64(x.hi_up());
      }
      o.i32(d.parent_split);
      o.i32(d.node);
    }
    for (size_t k = 0; k < st.deferred.size(); ++k) {
      o.u8(done[k]);
      if (!done[k]) continue;
      if (k < st.encoded.size() && !st.encoded[k].bytes.empty())  // as another rank encoded it
        o.bytes(st.encoded[k].bytes.data(), st.encoded[k].bytes.size());
      else
        write_search_part(o, st.parts[k], h.p);
      o.str(cert ? cert->records(int32_t(k)) : std::string());
    }
  }
  o.finish();
  f.commit();
}

Checkpoint read_checkpoint(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file)
    throw CheckpointError(path + ": no checkpoint to resume from (was the run started with "
                                 "--checkpoint SECONDS --out DIR?)");
  std::string b((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const size_t magic = std::strlen(kMagic);
  if (b.size() < magic || b.compare(0, magic, kMagic) != 0) {
    const size_t name = std::strlen("aspects-checkpoint ");
    const size_t eol = b.find('\n');
    if (b.compare(0, name, kMagic, name) == 0 && eol != std::string::npos && eol < 32)
      throw CheckpointError(path + ": an aspects checkpoint of format " +
                            b.substr(name, eol - name) + "; this version reads format " +
                            std::string(kMagic + name, magic - name - 1) +
                            ": resume it with the version that wrote it");
    throw CheckpointError(path + ": not an aspects checkpoint");
  }
  if (b.size() < magic + kDigest)
    throw CheckpointError(path + ": damaged checkpoint (truncated): refused, and left as it is");
  const size_t end = b.size() - kDigest;
  Sha256 sha;
  sha.add(b.data(), end);
  if (sha.digest() != b.substr(end))
    throw CheckpointError(path + ": damaged checkpoint (checksum mismatch: truncated or "
                                 "corrupted): refused, and left as it is");
  Checkpoint c;
  CheckpointHeader& h = c.header;
  In in(b, end, path);
  in.need(magic);
  for (size_t i = 0; i < magic; ++i) in.u8();
  h.version = in.str();
  h.model_sha256 = in.str();
  h.model_text = in.str();
  h.model_file = in.str();
  h.eps = in.f64();
  h.tau = in.f64();
  h.precision = in.i64();
  h.bisect = in.str();
  h.all_links = in.u8();
  h.no_cert = in.u8();
  h.cert_format = in.u8();
  h.defer_depth = in.i32();
  h.checkpoint_seconds = in.f64();
  h.nv = in.u32();
  h.p = in.u32();
  if (h.nv == 0 || h.nv > 16 || h.p > 20) in.fail("bad sizes");
  if (h.precision < 24 || h.precision > 4096) in.fail("bad precision");
  if (h.defer_depth < -1 || h.defer_depth > 64) in.fail("bad cut depth");
  if (h.cert_format != 2 && h.cert_format != 3) in.fail("bad certificate format");
  // The boxes below are intervals of the run's precision, as in the run that wrote them.
  set_working_precision(long(h.precision));
  if (sha256_hex(h.model_text) != h.model_sha256) in.fail("model text and hash differ");
  SearchState& st = c.state;
  st.top_done = in.u8();
  if (st.top_done) {
    read_search_part(in, st.top, h.nv, h.p, UINT32_MAX);
    c.top_records = in.str();
    const uint32_t marks = in.count(12);
    for (uint32_t i = 0; i < marks; ++i) {
      const int64_t offset = in.i64();
      const int32_t task = in.i32();
      const int64_t before = c.top_marks.empty() ? 0 : c.top_marks.back().first;
      // In order, inside the records and before their 16-byte trailer.
      if (offset < before || offset + 16 > int64_t(c.top_records.size()) || task < 0)
        in.fail("bad deferred subtree mark");
      c.top_marks.emplace_back(offset, task);
    }
    const uint32_t D = in.count(16 * uint64_t(h.nv) + 9);
    st.deferred.resize(D);
    for (DeferredSubtree& d : st.deferred) {
      d.box.resize(h.nv);
      for (Interval& x : d.box) {
        double lo = in.f64(), hi = in.f64();
        if (!(lo <= hi)) in.fail("bad box");
        x.set_hull(lo, hi);
      }
      d.parent_split = in.i32();
      d.node = in.i32();
    }
    st.done.assign(D, 0);
    st.parts.resize(D);
    c.records.resize(D);
    for (uint32_t k = 0; k < D; ++k) {
      st.done[k] = in.u8();
      if (!st.done[k]) continue;
      read_search_part(in, st.parts[k], h.nv, h.p, 0);
      c.records[k] = in.str();
    }
    for (const SearchNode& s : st.top.tree)
      if (s.fate == LeafFate::Deferred && !s.internal() && uint32_t(s.index) >= D)
        in.fail("bad deferred subtree");
    for (const auto& [offset, task] : c.top_marks)
      if (uint32_t(task) >= D) in.fail("bad deferred subtree mark");
  }
  if (!in.at_end()) in.fail("trailing bytes");
  return c;
}

}  // namespace aspects
