#include "results/result_index.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "generalized_aspects.h"
#include "io/atomic_file.h"
#include "io/le_reader.h"
#include "io/le_writer.h"
#include "link.h"
#include "model/model.h"
#include "results/sha256.h"

namespace aspects {

namespace {

// Layout (every integer and double little-endian; a string is a u32 length and bytes):
//   "aspects-index\n" u32 version
//   u32 nv  u32 n  u32 p  i64 precision_bits  f64 tau  f64 eps
//   str model_file  str model_source  p × (str origin  str text)
//   u32 csnc_count  u32 filtered
//   u32 S  S × (u32 id  i32 csnc  nv × (f64 lo  f64 hi)  p × i8 sign)
//   u32 U  U × (u32 id  u8 kind  n × (f64 lo  f64 hi))
//   u32 L  L × (u32 a  u32 b  u32 shift_code  n × f64 witness)
//   str certificate_file  str certificate_sha256   (both empty: no certificate)
//   "end-index\n"  32 bytes: SHA-256 of every byte before them
const char kMagic[] = "aspects-index\n";
const char kTrailer[] = "end-index\n";
constexpr size_t kChecksumBytes = 32;

// The index's bytes, into a string, or through a file in pieces of about a megabyte
// (on 3-RPR at eps 0.3 the whole index is over a gigabyte); every byte hashed, for the
// checksum that ends the index.
class Writer : public LeWriter {
 public:
  explicit Writer(AtomicFile* file = nullptr) : file_(file) {}
  void bytes(const void* p, size_t n) override {
    out_.append(static_cast<const char*>(p), n);
    if (file_ && out_.size() >= (size_t(1) << 20)) flush();
  }
  void str(const std::string& s) {
    u32(uint32_t(s.size()));
    bytes(s.data(), s.size());
  }
  // Appends the hash of every byte so far, the last bytes of the index; returns the hash
  // of the whole index, checksum included (what sha256sum prints of the file).
  std::string checksum() {
    hash_pending();
    out_ += hash_.peek_raw();
    hash_pending();
    return hash_.hex();
  }
  void flush() {
    hash_pending();
    file_->write(out_);
    out_.clear();
    hashed_ = 0;
  }
  std::string take() { return std::move(out_); }

 private:
  void hash_pending() {
    hash_.update(out_.data() + hashed_, out_.size() - hashed_);
    hashed_ = out_.size();
  }
  AtomicFile* file_;
  std::string out_;
  size_t hashed_ = 0;  // bytes of out_ already hashed
  Sha256Hasher hash_;
};

bool is_sha256_hex(const std::string& s) {
  return s.size() == 64 && std::all_of(s.begin(), s.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

class Reader : public LeReader {
 public:
  Reader(const std::string& b, const std::string& what) : LeReader(b, b.size()), what_(what) {}
  [[noreturn]] void fail(const std::string& msg) const override {
    throw IndexError(what_ + ": malformed result index at byte " + std::to_string(pos()) + ": " +
                     msg + " (re-run `aspects solve --out`)");
  }
  double f64() {
    double d = f64_bits();
    if (!std::isfinite(d)) fail("a number is not finite");
    return d;
  }
  std::string str(size_t max_len) {
    uint32_t n = u32();
    if (n > max_len) fail("string too long");
    return bytes(n);
  }

 private:
  std::string what_;
};

// certify_link's choice of witness (proofs/link.cpp): the midpoint of the inner
// intersection of the pose parts, box b shifted by 2πk.
std::vector<double> recompute_witness(const Model& m, const BoxStore& R, const NeighborPair& p) {
  std::vector<double> w(m.n(), 0.0);
  for (int j = 0; j < m.n(); ++j) {
    int v = m.pose[j];
    double lo, hi;
    if (inner_intersection(R.lo(p.a, v), R.hi(p.a, v), R.lo(p.b, v), R.hi(p.b, v), p.shift(v),
                           lo, hi))
      w[j] = Interval(lo, hi).mid();
  }
  return w;
}

}  // namespace

namespace {

// Everything of the index of `r` but its three lists.
ResultIndex index_header(const Model& model, const AspectsResult& r, long precision_bits,
                         double tau, double eps, const std::string& model_file) {
  ResultIndex idx;
  idx.model_file = model_file;
  idx.model_source = model.source;
  idx.precision_bits = precision_bits;
  idx.tau = tau;
  idx.eps = eps;
  idx.nv = uint32_t(r.boxes.ends().nv());
  idx.n = uint32_t(model.n());
  for (const auto& f : r.factors) idx.factors.push_back({f.origin, f.text});
  idx.csnc_count = uint32_t(r.csnc_sizes.size());
  idx.filtered = uint32_t(r.filtered);
  return idx;
}

// Where the records of an index go, in file order: into a ResultIndex
// (build_result_index) or straight to the file (write_result_index). The records are
// built one at a time in the same temporaries: held whole, they would take more memory than
// the search's boxes (three small vectors per box).
class RecordSink {
 public:
  virtual ~RecordSink() = default;
  virtual void begin_solutions(uint32_t count) = 0;
  virtual void solution(const IndexSolutionBox& s) = 0;
  virtual void begin_undecided(uint32_t count) = 0;
  virtual void undecided(const IndexUndecidedBox& u) = 0;
  virtual void begin_links(uint32_t count) = 0;
  virtual void link(const IndexLink& l) = 0;
};

// The solution boxes; returns each output box's place among them (-1: not one), for
// the links.
std::vector<int32_t> emit_solutions(const AspectsResult& r, RecordSink& sink) {
  const BoxStore& boxes = r.boxes.ends();
  const size_t p = r.factors.size();
  uint32_t solutions = 0;
  for (int b = 0; b < r.boxes.size(); ++b) solutions += r.boxes.certified(b);
  std::vector<int32_t> solution_index(r.boxes.size(), -1);
  IndexSolutionBox s;
  sink.begin_solutions(solutions);
  for (int b = 0, k = 0; b < r.boxes.size(); ++b) {
    if (!r.boxes.certified(b)) continue;
    s.id = uint32_t(b);
    s.csnc = r.csnc[b];
    s.lo.clear();
    s.hi.clear();
    for (int v = 0; v < boxes.nv(); ++v) {
      s.lo.push_back(boxes.lo(b, v));
      s.hi.push_back(boxes.hi(b, v));
    }
    s.signs.assign(r.boxes.signs(b), r.boxes.signs(b) + p);
    solution_index[b] = k++;
    sink.solution(s);
  }
  return solution_index;
}

// The other output boxes, by their pose part.
void emit_undecided(const Model& model, const AspectsResult& r, uint32_t solutions,
                    RecordSink& sink) {
  const BoxStore& boxes = r.boxes.ends();
  IndexUndecidedBox u;
  sink.begin_undecided(uint32_t(r.boxes.size()) - solutions);
  for (int b = 0; b < r.boxes.size(); ++b) {
    if (r.boxes.certified(b)) continue;
    u.id = uint32_t(b);
    u.kind = uint8_t(r.boxes.kind(b));
    u.lo.clear();
    u.hi.clear();
    for (int v : model.pose) {
      u.lo.push_back(boxes.lo(b, v));
      u.hi.push_back(boxes.hi(b, v));
    }
    sink.undecided(u);
  }
}

void emit_links(const Model& model, const AspectsResult& r,
                const std::vector<int32_t>& solution_index, RecordSink& sink) {
  const bool kept = r.link_proofs.size() == r.certified_links.size();
  IndexLink l;
  sink.begin_links(uint32_t(r.certified_links.size()));
  for (size_t i = 0; i < r.certified_links.size(); ++i) {
    const NeighborPair& pair = r.neighbors[r.certified_links[i]];
    l.a = uint32_t(solution_index[pair.a]);
    l.b = uint32_t(solution_index[pair.b]);
    l.shift_code = pair.shift_code;
    if (kept)
      l.witness.assign(r.link_proofs.witness(i), r.link_proofs.witness(i) + model.n());
    else
      l.witness = recompute_witness(model, r.boxes.ends(), pair);
    sink.link(l);
  }
}

void emit_records(const Model& model, const AspectsResult& r, RecordSink& sink) {
  const std::vector<int32_t> solution_index = emit_solutions(r, sink);
  const uint32_t solutions =
      uint32_t(std::count_if(solution_index.begin(), solution_index.end(),
                             [](int32_t k) { return k >= 0; }));
  emit_undecided(model, r, solutions, sink);
  emit_links(model, r, solution_index, sink);
}

class CollectRecords : public RecordSink {
 public:
  explicit CollectRecords(ResultIndex& idx) : idx_(idx) {}
  void begin_solutions(uint32_t count) override { idx_.solutions.reserve(count); }
  void solution(const IndexSolutionBox& s) override { idx_.solutions.push_back(s); }
  void begin_undecided(uint32_t count) override { idx_.undecided.reserve(count); }
  void undecided(const IndexUndecidedBox& u) override { idx_.undecided.push_back(u); }
  void begin_links(uint32_t count) override { idx_.links.reserve(count); }
  void link(const IndexLink& l) override { idx_.links.push_back(l); }

 private:
  ResultIndex& idx_;
};

}  // namespace

ResultIndex build_result_index(const Model& model, const AspectsResult& r, long precision_bits,
                               double tau, double eps, const std::string& model_file) {
  ResultIndex idx = index_header(model, r, precision_bits, tau, eps, model_file);
  CollectRecords collect(idx);
  emit_records(model, r, collect);
  return idx;
}

namespace {

void encode_header(const ResultIndex& idx, Writer& w) {
  w.bytes(kMagic, std::strlen(kMagic));
  w.u32(kResultIndexVersion);
  w.u32(idx.nv);
  w.u32(idx.n);
  w.u32(uint32_t(idx.factors.size()));
  w.i64(idx.precision_bits);
  w.f64(idx.tau);
  w.f64(idx.eps);
  w.str(idx.model_file);
  w.str(idx.model_source);
  for (const auto& f : idx.factors) {
    w.str(f.origin);
    w.str(f.text);
  }
  w.u32(idx.csnc_count);
  w.u32(idx.filtered);
}

void encode(const IndexSolutionBox& s, Writer& w) {
  w.u32(s.id);
  w.i32(s.csnc);
  for (size_t v = 0; v < s.lo.size(); ++v) {
    w.f64(s.lo[v]);
    w.f64(s.hi[v]);
  }
  for (int8_t g : s.signs) w.u8(uint8_t(g));
}

void encode(const IndexUndecidedBox& u, Writer& w) {
  w.u32(u.id);
  w.u8(u.kind);
  for (size_t j = 0; j < u.lo.size(); ++j) {
    w.f64(u.lo[j]);
    w.f64(u.hi[j]);
  }
}

void encode(const IndexLink& l, Writer& w) {
  w.u32(l.a);
  w.u32(l.b);
  w.u32(l.shift_code);
  for (double x : l.witness) w.f64(x);
}

// The certificate, the end marker and the checksum, which it returns.
std::string encode_trailer(const CertificateId& cert, Writer& w) {
  w.str(cert.file);
  w.str(cert.sha256);
  w.bytes(kTrailer, std::strlen(kTrailer));
  return w.checksum();
}

std::string encode(const ResultIndex& idx, Writer& w) {
  encode_header(idx, w);
  w.u32(uint32_t(idx.solutions.size()));
  for (const auto& s : idx.solutions) encode(s, w);
  w.u32(uint32_t(idx.undecided.size()));
  for (const auto& u : idx.undecided) encode(u, w);
  w.u32(uint32_t(idx.links.size()));
  for (const auto& l : idx.links) encode(l, w);
  return encode_trailer({idx.certificate_file, idx.certificate_sha256}, w);
}

// The records encoded as they come: the file, never the index, is whole.
class EncodeRecords : public RecordSink {
 public:
  explicit EncodeRecords(Writer& w) : w_(w) {}
  void begin_solutions(uint32_t count) override { w_.u32(count); }
  void solution(const IndexSolutionBox& s) override { encode(s, w_); }
  void begin_undecided(uint32_t count) override { w_.u32(count); }
  void undecided(const IndexUndecidedBox& u) override { encode(u, w_); }
  void begin_links(uint32_t count) override { w_.u32(count); }
  void link(const IndexLink& l) override { encode(l, w_); }

 private:
  Writer& w_;
};

}  // namespace

std::string encode_result_index(const ResultIndex& idx) {
  Writer w;
  encode(idx, w);
  return w.take();
}

ResultIndex decode_result_index(const std::string& bytes, const std::string& what) {
  Reader r(bytes, what);
  if (!r.literal(kMagic)) r.fail("not an aspects result index (bad magic)");
  uint32_t version = r.u32();
  if (version != kResultIndexVersion)
    throw IndexError(what + ": result index version " + std::to_string(version) +
                     ", this aspects reads version " + std::to_string(kResultIndexVersion) +
                     " (re-run `aspects solve --out`)");
  ResultIndex idx;
  idx.nv = r.u32();
  idx.n = r.u32();
  uint32_t p = r.u32();
  if (idx.n < 1 || idx.n > 8 || idx.nv != 2 * idx.n) r.fail("bad variable counts");
  if (p > 64) r.fail("too many factors");
  uint64_t prec = r.u64();
  if (prec < 24 || prec > 4096) r.fail("bad precision");
  idx.precision_bits = long(prec);
  idx.tau = r.f64();
  idx.eps = r.f64();
  if (!(idx.tau >= 1) || !(idx.eps > 0)) r.fail("bad tau or eps");
  idx.model_file = r.str(4096);
  idx.model_source = r.str(1u << 24);
  for (uint32_t i = 0; i < p; ++i) {
    IndexFactor f;
    f.origin = r.str(4096);
    f.text = r.str(1u << 20);
    idx.factors.push_back(std::move(f));
  }
  idx.csnc_count = r.u32();
  idx.filtered = r.u32();
  if (idx.filtered > idx.csnc_count) r.fail("more filtered CSNCs than CSNCs");
  uint32_t S = r.count(8 + 16 * size_t(idx.nv) + p);
  idx.solutions.resize(S);
  for (uint32_t i = 0; i < S; ++i) {
    IndexSolutionBox& s = idx.solutions[i];
    s.id = r.u32();
    if (i > 0 && s.id <= idx.solutions[i - 1].id) r.fail("solution box ids not increasing");
    s.csnc = r.i32();
    if (s.csnc < 0 || uint32_t(s.csnc) >= idx.csnc_count) r.fail("bad CSNC number");
    s.lo.resize(idx.nv);
    s.hi.resize(idx.nv);
    for (uint32_t v = 0; v < idx.nv; ++v) {
      s.lo[v] = r.f64();
      s.hi[v] = r.f64();
      if (!(s.lo[v] <= s.hi[v])) r.fail("reversed interval");
    }
    s.signs.resize(p);
    for (uint32_t k = 0; k < p; ++k) {
      s.signs[k] = int8_t(r.u8());
      if (s.signs[k] < -1 || s.signs[k] > 1) r.fail("bad sign");
    }
  }
  uint32_t U = r.count(5 + 16 * size_t(idx.n));
  idx.undecided.resize(U);
  for (uint32_t i = 0; i < U; ++i) {
    IndexUndecidedBox& u = idx.undecided[i];
    u.id = r.u32();
    if (i > 0 && u.id <= idx.undecided[i - 1].id) r.fail("undecided box ids not increasing");
    u.kind = r.u8();
    if (u.kind > 3) r.fail("bad undecided kind");
    u.lo.resize(idx.n);
    u.hi.resize(idx.n);
    for (uint32_t j = 0; j < idx.n; ++j) {
      u.lo[j] = r.f64();
      u.hi[j] = r.f64();
      if (!(u.lo[j] <= u.hi[j])) r.fail("reversed interval");
    }
  }
  uint32_t L = r.count(12 + 8 * size_t(idx.n));
  idx.links.resize(L);
  for (auto& l : idx.links) {
    l.a = r.u32();
    l.b = r.u32();
    if (!(l.a < l.b && l.b < S)) r.fail("bad link ends");
    l.shift_code = r.u32();
    if (idx.nv < 16 && (l.shift_code >> (2 * idx.nv)) != 0) r.fail("bad link shift");
    for (uint32_t v = 0; v < idx.nv; ++v)
      if (l.shift(int(v)) > 1) r.fail("bad link shift");
    l.witness.resize(idx.n);
    for (auto& x : l.witness) x = r.f64();
  }
  idx.certificate_file = r.str(64);
  idx.certificate_sha256 = r.str(64);
  if (!idx.certificate_file.empty() && idx.certificate_file != "aspects.cert" &&
      idx.certificate_file != "aspects.cert.zst")
    r.fail("bad certificate name");
  if (idx.certificate_file.empty() ? !idx.certificate_sha256.empty()
                                   : !is_sha256_hex(idx.certificate_sha256))
    r.fail("bad certificate hash");
  if (!r.literal(kTrailer) || r.left() != kChecksumBytes)
    r.fail("missing end marker or checksum");
  const size_t body = bytes.size() - kChecksumBytes;
  Sha256Hasher h;
  h.update(bytes.data(), body);
  const std::string raw = h.peek_raw();
  if (bytes.compare(body, kChecksumBytes, raw) != 0)
    throw IndexError(what + ": the result index does not match its checksum: damaged or "
                     "edited since `aspects solve` wrote it (re-run `aspects solve --out`)");
  h.update(raw.data(), raw.size());
  idx.sha256 = h.hex();
  return idx;
}

std::string write_result_index(const std::string& path, const ResultIndex& idx) {
  AtomicFile f(path);
  Writer w(&f);
  const std::string checksum = encode(idx, w);
  w.flush();
  f.commit();
  return checksum;
}

std::string write_result_index(const std::string& path, const Model& model,
                               const AspectsResult& r, long precision_bits, double tau,
                               double eps, const std::string& model_file,
                               const std::function<CertificateId()>& certificate) {
  AtomicFile f(path);
  Writer w(&f);
  encode_header(index_header(model, r, precision_bits, tau, eps, model_file), w);
  EncodeRecords encode_records(w);
  emit_records(model, r, encode_records);
  const std::string checksum = encode_trailer(certificate(), w);
  w.flush();
  f.commit();
  return checksum;
}

ResultIndex read_result_index(const std::string& result_dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (result_dir.find('\0') != std::string::npos)
    throw IndexError("RESULT_DIR: the path contains a NUL character");
  if (!fs::is_directory(result_dir, ec))
    throw IndexError("RESULT_DIR " + result_dir + ": no such directory");
  std::string path = (fs::path(result_dir) / kResultIndexName).string();
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw IndexError("RESULT_DIR " + result_dir + ": no " + kResultIndexName +
                     " (written by `aspects solve --out DIR`)");
  std::ostringstream os;
  os << in.rdbuf();
  return decode_result_index(os.str(), path);
}

}  // namespace aspects
