#include "results/count_pieces.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "io/atomic_file.h"
#include "io/le_reader.h"
#include "io/le_writer.h"
#include "results/result_index.h"
#include "results/sha256.h"

namespace aspects {

namespace {

// Layout (little-endian; a string is a u32 length and bytes; a list a u32 count):
//   "aspects-count-pieces\n" u32 version
//   u32 nv  u32 n  u32 p  i64 precision_bits  f64 eps  i32 lower  i32 upper
//   str model_file  str model_source  p × str factor
//   u32 C  C × (i32 id  nv × (f64 lo  f64 hi)  n × i32 w
//               u32 P  P × (u32 cls  u8 how  u8 has_point
//                           [n × i32 w_var  n × f64 u  n × (f64 lo  f64 hi)]))
//   u32 J  J × (i32 a  i32 b  u32 cls  nv × i8 shift  u8 bridge  n × i32 w
//               [n × f64 u  n × (f64 lo  f64 hi)]   (a point only))
//   "end-count-pieces\n"  32 bytes: SHA-256 of every byte before them
const char kMagic[] = "aspects-count-pieces\n";
const char kTrailer[] = "end-count-pieces\n";
constexpr size_t kChecksumBytes = 32;

std::string raw_sha256(const char* data, size_t n) {
  Sha256Hasher h;
  h.update(data, n);
  return h.raw();
}

class Writer : public LeWriter {
 public:
  void bytes(const void* p, size_t n) override { out_.append(static_cast<const char*>(p), n); }
  void str(const std::string& s) {
    u32(uint32_t(s.size()));
    bytes(s.data(), s.size());
  }
  std::string out_;
};

class Reader : public LeReader {
 public:
  Reader(const std::string& b, const std::string& what) : LeReader(b, b.size()), what_(what) {}
  [[noreturn]] void fail(const std::string& msg) const override {
    throw IndexError(what_ + ": malformed count pieces file at byte " + std::to_string(pos()) +
                     ": " + msg + " (re-run `aspects count --out`)");
  }
  double f64() {
    const double d = f64_bits();
    if (!std::isfinite(d)) fail("a number is not finite");
    return d;
  }
  std::string str(size_t max_len) {
    const uint32_t n = u32();
    if (n > max_len) fail("string too long");
    return bytes(n);
  }
  // n distinct variable indices below nv.
  std::vector<int> vars(uint32_t n, uint32_t nv) {
    std::vector<int> v(n);
    for (int& x : v) {
      x = i32();
      if (x < 0 || uint32_t(x) >= nv) fail("bad variable index");
    }
    std::vector<int> s = v;
    std::sort(s.begin(), s.end());
    if (std::adjacent_find(s.begin(), s.end()) != s.end()) fail("repeated variable");
    return v;
  }
  std::vector<double> pairs(uint32_t n) {
    std::vector<double> v(2 * n);
    for (uint32_t i = 0; i < n; ++i) {
      v[2 * i] = f64();
      v[2 * i + 1] = f64();
      if (!(v[2 * i] <= v[2 * i + 1])) fail("reversed interval");
    }
    return v;
  }
  std::vector<double> reals(uint32_t n) {
    std::vector<double> v(n);
    for (double& x : v) x = f64();
    return v;
  }

 private:
  std::string what_;
};

}  // namespace

CountPieces count_pieces_of(const Model& model, const CountResult& r, double eps,
                            long precision_bits) {
  CountPieces out;
  out.model_file = model.file;
  out.model_source = model.source;
  out.precision_bits = precision_bits;
  out.eps = eps;
  out.lower = r.bounds.lower;
  out.upper = r.bounds.upper;
  out.factors = r.factor_text;
  out.nv = uint32_t(model.vars.size());
  out.n = uint32_t(model.n());
  if (!r.records) return out;
  const CountRecords& rec = *r.records;
  // cell id -> index in out.cells; the classes each kept cell has connected.
  std::map<int32_t, size_t> kept;
  for (size_t id = 0; id < rec.cells.size(); ++id) {
    const CountCellRecord& c = rec.cells[id];
    if (!c.alive) continue;
    CountPieceCell cell;
    cell.id = int32_t(id);
    cell.box = c.box;
    // A cell with no fit and a connected piece is a solve's solution box: its chart is P1's,
    // the commands over the pose.
    cell.w = c.fit == CountCellRecord::Charted ? c.w : model.command;
    if (c.fit != CountCellRecord::Charted && c.fit != CountCellRecord::NoFit) continue;
    for (const CountCellRecord::Piece& p : c.pieces) {
      if (p.state != PieceState::Connected || p.connected_by == CountCellRecord::NotConnected)
        continue;
      CountPiece q;
      q.cls = p.cls;
      q.how = p.connected_by == CountCellRecord::Star ? CountPiece::Star : CountPiece::Graph;
      if (!p.point_u.empty()) q.w_vars = p.point_w, q.u = p.point_u, q.hint = p.point_hint;
      cell.pieces.push_back(std::move(q));
    }
    if (cell.pieces.empty()) continue;
    std::sort(cell.pieces.begin(), cell.pieces.end(),
              [](const CountPiece& a, const CountPiece& b) { return a.cls < b.cls; });
    kept[cell.id] = out.cells.size();
    out.cells.push_back(std::move(cell));
  }
  auto has = [&](int32_t id, uint32_t cls) {
    const auto it = kept.find(id);
    if (it == kept.end()) return false;
    for (const CountPiece& p : out.cells[it->second].pieces)
      if (p.cls == cls) return true;
    return false;
  };
  for (const CountRecords::Joined& j : rec.joined) {
    if (!has(j.a, j.cls) || !has(j.b, j.cls)) continue;
    CountJoin q;
    q.a = j.a, q.b = j.b, q.cls = j.cls, q.bridge = j.bridge, q.w = j.w;
    for (int k : j.shift) q.shift.push_back(int8_t(k));
    if (!j.bridge) q.u = j.u, q.hint = j.hint;
    out.joins.push_back(std::move(q));
  }
  return out;
}

std::string encode_count_pieces(const CountPieces& P) {
  Writer w;
  w.bytes(kMagic, sizeof(kMagic) - 1);
  w.u32(kCountPiecesVersion);
  w.u32(P.nv);
  w.u32(P.n);
  w.u32(uint32_t(P.factors.size()));
  w.i64(P.precision_bits);
  w.f64(P.eps);
  w.i32(P.lower);
  w.i32(P.upper);
  w.str(P.model_file);
  w.str(P.model_source);
  for (const std::string& f : P.factors) w.str(f);
  w.u32(uint32_t(P.cells.size()));
  for (const CountPieceCell& c : P.cells) {
    w.i32(c.id);
    for (double x : c.box) w.f64(x);
    for (int v : c.w) w.i32(v);
    w.u32(uint32_t(c.pieces.size()));
    for (const CountPiece& p : c.pieces) {
      w.u32(p.cls);
      w.u8(uint8_t(p.how));
      w.u8(!p.w_vars.empty());
      if (p.w_vars.empty()) continue;
      for (int v : p.w_vars) w.i32(v);
      for (double x : p.u) w.f64(x);
      for (double x : p.hint) w.f64(x);
    }
  }
  w.u32(uint32_t(P.joins.size()));
  for (const CountJoin& j : P.joins) {
    w.i32(j.a);
    w.i32(j.b);
    w.u32(j.cls);
    for (int8_t k : j.shift) w.u8(uint8_t(k));
    w.u8(j.bridge);
    for (int v : j.w) w.i32(v);
    if (j.bridge) continue;
    for (double x : j.u) w.f64(x);
    for (double x : j.hint) w.f64(x);
  }
  w.bytes(kTrailer, sizeof(kTrailer) - 1);
  w.out_ += raw_sha256(w.out_.data(), w.out_.size());
  return std::move(w.out_);
}

CountPieces decode_count_pieces(const std::string& bytes, const std::string& what) {
  Reader r(bytes, what);
  if (!r.literal(kMagic)) r.fail("not an aspects count pieces file (bad magic)");
  const uint32_t version = r.u32();
  if (version != kCountPiecesVersion)
    throw IndexError(what + ": count pieces version " + std::to_string(version) +
                     ", this aspects reads version " + std::to_string(kCountPiecesVersion) +
                     " (re-run `aspects count --out`)");
  CountPieces P;
  P.nv = r.u32();
  P.n = r.u32();
  const uint32_t p = r.u32();
  if (P.n < 1 || P.n > 8 || P.nv != 2 * P.n) r.fail("bad variable counts");
  if (p > 6) r.fail("too many factors");
  const int64_t prec = r.i64();
  if (prec < 24 || prec > 4096) r.fail("bad precision");
  P.precision_bits = long(prec);
  P.eps = r.f64();
  if (!(P.eps > 0)) r.fail("bad eps");
  P.lower = r.i32();
  P.upper = r.i32();
  if (P.lower < 0 || P.upper < -1 || (P.upper >= 0 && P.upper < P.lower)) r.fail("bad bounds");
  P.model_file = r.str(4096);
  P.model_source = r.str(1u << 24);
  for (uint32_t i = 0; i < p; ++i) P.factors.push_back(r.str(1u << 20));
  const uint32_t C = r.count(12 + 16 * size_t(P.nv));
  std::map<int32_t, size_t> index;
  for (uint32_t i = 0; i < C; ++i) {
    CountPieceCell c;
    c.id = r.i32();
    if (c.id < 0 || (i > 0 && c.id <= P.cells.back().id)) r.fail("cell ids not increasing");
    c.box = r.pairs(P.nv);
    c.w = r.vars(P.n, P.nv);
    const uint32_t np = r.count(6);
    for (uint32_t k = 0; k < np; ++k) {
      CountPiece q;
      q.cls = r.u32();
      if (q.cls >> p) r.fail("bad class");
      if (k > 0 && q.cls <= c.pieces.back().cls) r.fail("classes not increasing");
      const uint8_t how = r.u8();
      if (how != CountPiece::Graph && how != CountPiece::Star) r.fail("bad piece kind");
      q.how = CountPiece::How(how);
      const uint8_t has_point = r.u8();
      if (has_point > 1) r.fail("bad point flag");
      if (has_point) {
        q.w_vars = r.vars(P.n, P.nv);
        q.u = r.reals(P.n);
        q.hint = r.pairs(P.n);
      } else if (q.how == CountPiece::Star) {
        r.fail("a star-shaped piece without its centre");
      }
      c.pieces.push_back(std::move(q));
    }
    index[c.id] = P.cells.size();
    P.cells.push_back(std::move(c));
  }
  const uint32_t J = r.count(14 + P.nv);
  for (uint32_t i = 0; i < J; ++i) {
    CountJoin j;
    j.a = r.i32();
    j.b = r.i32();
    j.cls = r.u32();
    if (!index.count(j.a) || !index.count(j.b) || j.a == j.b) r.fail("bad join ends");
    if (j.cls >> p) r.fail("bad class");
    for (uint32_t v = 0; v < P.nv; ++v) {
      j.shift.push_back(int8_t(r.u8()));
      if (j.shift.back() < -1 || j.shift.back() > 1) r.fail("bad join shift");
    }
    const uint8_t bridge = r.u8();
    if (bridge > 1) r.fail("bad bridge flag");
    j.bridge = bridge;
    j.w = r.vars(P.n, P.nv);
    if (!j.bridge) {
      j.u = r.reals(P.n);
      j.hint = r.pairs(P.n);
    }
    P.joins.push_back(std::move(j));
  }
  if (!r.literal(kTrailer) || r.left() != kChecksumBytes) r.fail("missing end marker or checksum");
  const size_t body = bytes.size() - kChecksumBytes;
  if (bytes.compare(body, kChecksumBytes, raw_sha256(bytes.data(), body)) != 0)
    throw IndexError(what + ": the count pieces file does not match its checksum: damaged or "
                     "edited since `aspects count --out` wrote it (re-run it)");
  P.sha256 = sha256_hex_of(bytes);
  return P;
}

void write_count_pieces(const std::string& path, const CountPieces& pieces) {
  write_file_atomically(path, encode_count_pieces(pieces));
}

bool is_count_directory(const std::string& dir) {
  std::error_code ec;
  return dir.find('\0') == std::string::npos &&
         std::filesystem::is_regular_file(std::filesystem::path(dir) / kCountPiecesName, ec);
}

CountPieces read_count_pieces(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (dir.find('\0') != std::string::npos)
    throw IndexError("DIR: the path contains a NUL character");
  if (!fs::is_directory(dir, ec)) throw IndexError("DIR " + dir + ": no such directory");
  const std::string path = (fs::path(dir) / kCountPiecesName).string();
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw IndexError("DIR " + dir + ": no " + std::string(kCountPiecesName) +
                     " (written by `aspects count MODEL --out DIR`)");
  std::ostringstream os;
  os << in.rdbuf();
  return decode_count_pieces(os.str(), path);
}

}  // namespace aspects
