#include "certificate_writer.h"

#include <openssl/sha.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdarg>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "aspects_version.h"
#include "compressed_output.h"
#include "hashing_output.h"

namespace aspects {

const char* const kToolVersion = ASPECTS_VERSION_FULL;  // one token: `tool aspects <version>`

namespace {
std::string sha256_hex(const std::string& data) {
  unsigned char d[SHA256_DIGEST_LENGTH];
  SHA256(reinterpret_cast<const unsigned char*>(data.data()), data.size(), d);
  static const char* hex = "0123456789abcdef";
  std::string s;
  for (unsigned char c : d) {
    s += hex[c >> 4];
    s += hex[c & 15];
  }
  return s;
}
}  // namespace

CertificateWriter::CertificateWriter(const std::string& path, const Model& model,
                                     long precision, double tau, double eps, bool compress,
                                     int format)
    : file_(path), format_(format), model_(model) {
  // Level 3 (zstd's default) on one helper thread, beside the writing of the records
  // (bench/RESULTS.md has the sizes).
  if (compress && !(compressor_ = open_compressed_output(file_.stream(), 3, 1)))
    throw std::runtime_error("cannot compress " + file_.temporary_path() + ": " +
                             std::strerror(errno));
  // Hashed before compression, as check_cert hashes what it reads.
  if (!(f_ = open_hashing_output(compressor_ ? compressor_ : file_.stream(), &sha256_))) {
    const int err = errno;
    if (compressor_) std::fclose(compressor_);
    throw std::runtime_error("cannot hash " + file_.temporary_path() + ": " + std::strerror(err));
  }
  buffer_.reset(new char[kBuffer]);
  std::setvbuf(f_, buffer_.get(), _IOFBF, kBuffer);
  n_ = model.n();
  line("aspects-certificate " + std::to_string(format));
  line(std::string("tool aspects ") + kToolVersion);
  line("model " + std::to_string(model.source.size()) + " " + sha256_hex(model.source));
  std::fwrite(model.source.data(), 1, model.source.size(), f_);
  for (char c : model.source) lines_ += (c == '\n');
  bytes_ += long(model.source.size());
  line("");  // the newline that ends the model text
  line("end-model");
  line("precision " + std::to_string(precision));
  put("tau %a", tau);
  end_line();
  put("eps %a", eps);
  end_line();
}

// An unfinished certificate's temporary is removed by file_.
CertificateWriter::~CertificateWriter() {
  std::free(line_);
  if (f_) std::fclose(f_);
  if (compressor_) std::fclose(compressor_);
  if (spool_) {
    std::fclose(spool_);
    std::remove((file_.temporary_path() + ".restored").c_str());
  }
}

void CertificateWriter::line(const std::string& s) {
  std::fputs(s.c_str(), f_);
  bytes_ += long(s.size());
  end_line();
}

void CertificateWriter::put(const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  int k = std::vfprintf(f_, fmt, ap);
  va_end(ap);
  if (k > 0) bytes_ += k;
}

void CertificateWriter::end_line() {
  std::fputc('\n', f_);
  ++bytes_;
  ++lines_;
}

void CertificateWriter::real(double x) { put(" %a", x); }

void CertificateWriter::interval(const Interval& x) {
  real(x.lo_down());
  real(x.hi_up());
}

void CertificateWriter::begin(const Box& domain, const std::vector<Factor>& factors) {
  p_ = int(factors.size());
  put("domain");
  for (const auto& x : domain) interval(x);
  end_line();
  line("factors " + std::to_string(p_));
  for (const auto& f : factors) line("factor " + f.kind);
  line("tree");
  if (!top_)  // else restored
    top_ = std::make_unique<TreeRecordFile>(
        file_.temporary_path() + ".top", p_, n_,
        format_ == 3 ? compact_tree(domain, model_, p_) : nullptr);
}

std::string CertificateWriter::records(int32_t task) {
  if (held(task))
    throw std::logic_error("the records of subtree " + std::to_string(task) +
                           " are held by another process");
  TreeRecordFile& part = task < 0 ? *top_ : *tasks_.at(task);
  part.close();
  long size = 0;
  FILE* in = open_records(part, &size);
  std::string text(size_t(size), '\0');
  const bool ok = std::fread(&text[0], 1, text.size(), in) == text.size();
  std::fclose(in);
  if (!ok) throw std::runtime_error("cannot read " + part.path());
  return text;
}

std::vector<TreeRecordFile::Mark> CertificateWriter::marks(int32_t task) const {
  return (task < 0 ? *top_ : *tasks_.at(task)).marks();
}

void CertificateWriter::restore(int32_t task, const std::string& records,
                                std::vector<TreeRecordFile::Mark> marks) {
  std::unique_ptr<TreeRecordFile>* slot = &top_;
  if (task >= 0) {
    if (int32_t(tasks_.size()) <= task) tasks_.resize(task + 1);
    slot = &tasks_[task];
  }
  const std::string spool = file_.temporary_path() + ".restored";
  if (!spool_ && !(spool_ = std::fopen(spool.c_str(), "w+b")))
    throw std::runtime_error("cannot write " + spool + ": " + std::strerror(errno));
  if (std::fwrite(records.data(), 1, records.size(), spool_) != records.size())
    throw std::runtime_error("cannot write " + spool + ": " + std::strerror(errno ? errno : EIO));
  *slot = std::make_unique<TreeRecordFile>(spool, spool_size_,
                                           spool_size_ + long(records.size()), format_ == 3);
  (*slot)->set_marks(std::move(marks));
  spool_size_ += long(records.size());
}

void CertificateWriter::restore_later(int32_t task, std::function<std::string()> fetch) {
  if (int32_t(held_.size()) <= task) held_.resize(task + 1);
  held_[task] = std::move(fetch);
}

TreeRecordFile& CertificateWriter::task_records(int32_t task) {
  if (held(task)) {
    const std::function<std::string()> fetch = std::move(held_[task]);
    held_[task] = nullptr;
    if (int32_t(tasks_.size()) <= task) tasks_.resize(task + 1);
    tasks_[task] = std::make_unique<TreeRecordFile>(fetch(), format_ == 3);
  }
  return *tasks_.at(task);
}

FILE* CertificateWriter::open_records(TreeRecordFile& stream, long* size) {
  if (stream.in_memory()) {
    std::string& m = stream.memory();
    *size = long(m.size());
    FILE* in = m.empty() ? std::fopen("/dev/null", "rb") : fmemopen(m.data(), m.size(), "rb");
    if (!in) throw std::runtime_error("cannot read " + stream.path());
    return in;
  }
  if (stream.shared() && spool_ && std::fflush(spool_) != 0)
    throw std::runtime_error("cannot write " + stream.path() + ": " + std::strerror(errno));
  FILE* in = std::fopen(stream.path().c_str(), "rb");
  if (!in) throw std::runtime_error("cannot read " + stream.path());
  long end = stream.end();
  if (end < 0) {
    std::fseek(in, 0, SEEK_END);
    end = std::ftell(in);
  }
  *size = end - stream.begin();
  if (*size < 0 || std::fseek(in, stream.begin(), SEEK_SET) != 0) {
    std::fclose(in);
    throw std::runtime_error("cannot read " + stream.path());
  }
  return in;
}

// Spliced: its disk space is free for the rest (3-RPR at eps 0.1: 48 GB of records); a
// range of the spool is punched out of it (where the filesystem can).
void CertificateWriter::spliced(TreeRecordFile& stream) {
  if (stream.in_memory()) {
    std::string().swap(stream.memory());
  } else if (!stream.shared()) {
    std::remove(stream.path().c_str());
  } else if (spool_ && stream.end() > stream.begin()) {
    fallocate(fileno(spool_), FALLOC_FL_PUNCH_HOLE | FALLOC_FL_KEEP_SIZE, stream.begin(),
              stream.end() - stream.begin());
  }
}

TreeSink* CertificateWriter::subtree(int32_t task, const Box& root) {
  if (int32_t(tasks_.size()) <= task) tasks_.resize(task + 1);
  const std::string name = file_.temporary_path() + ".t" + std::to_string(task);
  tasks_[task] = std::make_unique<TreeRecordFile>(
      name, p_, n_, format_ == 3 ? compact_tree(root, model_, p_) : nullptr);
  return tasks_[task].get();
}

// One part's records being copied into the certificate, up to its next deferred subtree.
struct CertificateWriter::Splicing {
  TreeRecordFile* stream = nullptr;
  struct Close {
    void operator()(FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<FILE, Close> in;
  long left = 0;  // format 2: bytes not read yet; format 3: the records' bytes (no trailer)
  long at = 0;    // format 3: bytes copied
  size_t mark = 0;  // format 3: the next of stream->marks()
  uint64_t count[2] = {0, 0};  // format 3: the trailer's records and leaves
};

// Copies the top's records, each deferred subtree's records spliced at its place, depth
// first: output boxes get their global ids (format 2; format 3's are implied). The parts
// being copied are an explicit stack, not recursion, whatever the nesting.
void CertificateWriter::splice(TreeRecordFile& top) {
  std::vector<Splicing> stack;
  stack.push_back(open_splicing(top));
  while (!stack.empty()) {
    TreeRecordFile* next = copy_until_subtree(stack.back());
    if (next) {
      stack.push_back(open_splicing(*next));
      continue;
    }
    end_splicing(stack.back());
    stack.pop_back();
  }
}

CertificateWriter::Splicing CertificateWriter::open_splicing(TreeRecordFile& stream) {
  stream.close();
  Splicing s;
  s.stream = &stream;
  long all = 0;
  s.in.reset(open_records(stream, &all));
  s.left = all;
  if (!stream.binary()) return s;
  // Format 3: the trailer gives the records and leaves the part counts.
  unsigned char trailer[16];
  s.left = all - 16;
  FILE* in = s.in.get();
  if (s.left < 0 || std::fseek(in, stream.begin() + s.left, SEEK_SET) != 0 ||
      std::fread(trailer, 1, 16, in) != 16 || std::fseek(in, stream.begin(), SEEK_SET) != 0)
    throw std::runtime_error("cannot read " + stream.path());
  for (int i = 0; i < 16; ++i) s.count[i / 8] |= uint64_t(trailer[i]) << (8 * (i % 8));
  return s;
}

// Copies `s`'s records up to its next deferred subtree, which it returns (null: to its end).
TreeRecordFile* CertificateWriter::copy_until_subtree(Splicing& s) {
  FILE* in = s.in.get();
  if (s.stream->binary()) {
    // Format 3: the records as they are (ids are implied), each subtree at its mark.
    const std::vector<TreeRecordFile::Mark>& marks = s.stream->marks();
    const bool subtree = s.mark < marks.size();
    const long to = subtree ? marks[s.mark].offset : s.left;
    if (copy_buffer_.empty()) copy_buffer_.resize(1 << 20);
    while (s.at < to) {
      const size_t want = size_t(std::min<long>(to - s.at, long(copy_buffer_.size())));
      const size_t k = std::fread(copy_buffer_.data(), 1, want, in);
      if (k == 0) throw std::runtime_error("cannot read " + s.stream->path());
      std::fwrite(copy_buffer_.data(), 1, k, f_);
      s.at += long(k);
    }
    return subtree ? &task_records(marks[s.mark++].task) : nullptr;
  }
  ssize_t len;
  while (s.left > 0 && (len = getline(&line_, &line_size_, in)) > 0) {
    const char* buf = line_;
    s.left -= long(len);
    if (buf[0] == '@') return &task_records(int32_t(std::stol(buf + 1)));
    if ((buf[0] == 'U' || buf[0] == 'S' || buf[0] == 'N') && buf[1] == ' ') {
      const char* rest = std::strchr(buf + 2, ' ');
      put("%c %ld", buf[0], leaves_++);
      std::fputs(rest, f_);  // keeps the newline
      bytes_ += long(std::strlen(rest));
      ++lines_;
      continue;
    }
    std::fwrite(buf, 1, size_t(len), f_);
    bytes_ += len;
    ++lines_;
  }
  if (s.left != 0) throw std::runtime_error("cannot read " + s.stream->path());
  return nullptr;
}

void CertificateWriter::end_splicing(Splicing& s) {
  s.in.reset();
  if (s.stream->binary()) {
    bytes_ += s.left;
    lines_ += long(s.count[0]);
    leaves_ += long(s.count[1]);
  }
  spliced(*s.stream);
}

std::unique_ptr<CompactTree> compact_tree(const Box& root, const Model& model, int factors) {
  return std::make_unique<CompactTree>(compact::ends(root), model.command, factors);
}

// ---------------------------------------------------------------- TreeRecordFile

TreeRecordFile::TreeRecordFile(const std::string& path, int factors, int n,
                               std::unique_ptr<CompactTree> compact)
    : path_(path), p_(factors), n_(n), compact_(std::move(compact)), binary_(bool(compact_)) {
  f_ = std::fopen(path_.c_str(), "wb");
  if (!f_) throw std::runtime_error("cannot write " + path_);
}

TreeRecordFile::TreeRecordFile(const std::string& path, long begin, long end, bool binary)
    : path_(path), begin_(begin), end_(end), binary_(binary), trailer_(binary) {}

TreeRecordFile::TreeRecordFile(std::string records, bool binary)
    : path_("(records fetched from another process)"), begin_(0), end_(long(records.size())),
      binary_(binary), trailer_(binary), in_memory_(true), memory_(std::move(records)) {}

TreeRecordFile::~TreeRecordFile() {
  if (f_) std::fclose(f_);
  if (!shared()) std::remove(path_.c_str());
}

void TreeRecordFile::close() {
  if (!f_) return;
  if (binary_ && !trailer_) {
    trailer_ = true;
    record_.clear();
    compact::u64(record_, records_);
    compact::u64(record_, leaves_);
    std::fwrite(record_.data(), 1, record_.size(), f_);
  }
  // A write that failed earlier (disk full) leaves only the error flag: check it too.
  bool ok = !std::ferror(f_);
  ok = std::fclose(f_) == 0 && ok;
  f_ = nullptr;
  if (!ok) throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno ? errno : EIO));
}

void TreeRecordFile::signs(const int8_t* s) {
  std::fputc(' ', f_);
  if (p_ == 0) std::fputc('.', f_);
  for (int i = 0; i < p_; ++i) std::fputc(s[i] > 0 ? '+' : s[i] < 0 ? '-' : '0', f_);
}

void TreeRecordFile::emit() {
  std::fwrite(record_.data(), 1, record_.size(), f_);
  record_.clear();
  ++records_;
}

void TreeRecordFile::contraction(int var, double lo, double hi) {
  if (compact_) return compact_->contraction(var, lo, hi, record_), emit();
  std::fprintf(f_, "P %d %a %a\n", var, lo, hi);
}

void TreeRecordFile::split(int var, double at) {
  if (compact_) return compact_->split(var, at, record_), emit();
  std::fprintf(f_, "B %d %a\n", var, at);
}

void TreeRecordFile::discard(const char* hint) {
  if (compact_) return compact_->discard(hint, record_), emit();
  std::fprintf(f_, "X %s\n", hint);
}

void TreeRecordFile::deferred(int32_t task) {
  if (!compact_) {
    std::fprintf(f_, "@%d\n", task);
    return;
  }
  compact_->deferred();
  marks_.push_back({std::ftell(f_), task});
}

void TreeRecordFile::undecided(int32_t id, const int8_t* s) {
  if (compact_) return compact_->leaf(false, s, record_), ++leaves_, emit();
  std::fprintf(f_, "U %d", id);
  signs(s);
  std::fputc('\n', f_);
}

void TreeRecordFile::unexplored(int32_t id, const int8_t* s) {
  if (compact_) return compact_->leaf(true, s, record_), ++leaves_, emit();
  std::fprintf(f_, "N %d", id);
  signs(s);
  std::fputc('\n', f_);
}

void TreeRecordFile::solution(int32_t id, const int8_t* s, const SolutionProof& proof) {
  if (compact_) {
    std::vector<double> weights(proof.dx);
    weights.insert(weights.end(), proof.dq.begin(), proof.dq.end());
    compact_->solution(s, compact::ends(proof.existence.inflated),
                       compact::ends(proof.existence.image), weights, record_);
    ++leaves_;
    return emit();
  }
  std::fprintf(f_, "S %d", id);
  signs(s);
  auto interval = [&](const Interval& x) { std::fprintf(f_, " %a %a", x.lo_down(), x.hi_up()); };
  for (const auto& q : proof.existence.inflated) interval(q);
  for (const auto& q : proof.existence.image) interval(q);
  const std::vector<double>* reals[] = {&proof.existence.C, &proof.cx, &proof.cq, &proof.dx,
                                        &proof.dq};
  for (const auto* m : reals)
    for (double c : *m) std::fprintf(f_, " %a", c);
  std::fputc('\n', f_);
}

void CertificateWriter::finish(const Model& model, const AspectsResult& r) {
  splice(*top_);
  line("end-tree " + std::to_string(leaves_));
  const int nv = int(model.vars.size());
  line("links " + std::to_string(r.certified_links.size()));
  links(model, r);
  csncs(r);
  line("cuspidal " + std::to_string(r.cuspidal.pose.size()));
  for (const PoseWitness& w : r.cuspidal.pose) {
    std::string shift;
    for (int v = 0; v < nv; ++v) shift += "-0+"[w.shift(v) + 1];
    put("W %d %d %d %s", w.csnc, w.a, w.b, shift.c_str());
    end_line();
  }
  line("assembly " + std::to_string(r.cuspidal.command.size()));
  for (const CommandWitness& w : r.cuspidal.command) {
    std::string shift;
    for (int v = 0; v < nv; ++v) shift += "-0+"[w.shift(v) + 1];
    put("V %d %d %d %s", w.csnc, w.a, w.b, shift.c_str());
    for (double q : w.q) real(q);
    for (const Interval& x : w.xa) interval(x);
    for (double c : w.ca) real(c);
    for (const Interval& x : w.xb) interval(x);
    for (double c : w.cb) real(c);
    end_line();
  }
  line("claim filtered " + std::to_string(r.filtered));
  line("claim lower-bound " + std::to_string(r.separation.lower_bound));
  line("end " + std::to_string(lines_));
  close();
}

void CertificateWriter::binary(const std::string& record) {
  std::fwrite(record.data(), 1, record.size(), f_);
  bytes_ += long(record.size());
  ++lines_;
}

// Format 2 links as text; format 3 links: A as a step from the previous A, B − A − 1, the shift two bits a
// variable, the witness on the grid of A's pose, Q~ on the grid of A's commands.
void CertificateWriter::links(const Model& model, const AspectsResult& r) {
  const int nv = int(model.vars.size()), n = model.n();
  const LinkRecords& lp = r.link_proofs;
  int32_t last_a = 0;
  for (size_t i = 0; i < r.certified_links.size(); ++i) {
    const NeighborPair& e = r.neighbors[r.certified_links[i]];
    if (i >= lp.size()) throw std::logic_error("certificate: a certified link without its proof");
    if (format_ == 2) {
      std::string shift;
      for (int v = 0; v < nv; ++v) shift += "-0+"[e.shift(v) + 1];
      put("K %d %d %s", e.a, e.b, shift.c_str());
      for (int j = 0; j < n; ++j) real(lp.witness(i)[j]);
      for (int j = 0; j < n; ++j) {
        real(lp.inflated_lo(i, j));
        real(lp.inflated_hi(i, j));
      }
      for (int k = 0; k < n * n; ++k) real(lp.C(i)[k]);
      end_line();
      continue;
    }
    record_.assign(1, char(0xC4));
    compact::varint(record_, uint64_t(e.a - last_a));
    compact::varint(record_, uint64_t(e.b - e.a - 1));
    last_a = e.a;
    std::string shift;
    for (int v = 0; v < nv; ++v) shift += "0+-"[e.shift(v) == 1 ? 1 : e.shift(v) == -1 ? 2 : 0];
    compact::signs(record_, shift.c_str(), nv);
    const auto box_end = [&](int v, bool hi) { return hi ? r.boxes.hi(e.a, v) : r.boxes.lo(e.a, v); };
    for (int j = 0; j < n; ++j) {
      const int v = model.pose[j];
      compact::end(record_, lp.witness(i)[j], box_end(v, false), box_end(v, true), box_end(v, false));
    }
    for (int j = 0; j < n; ++j) {
      const int v = model.command[j];
      const double a = box_end(v, false), b = box_end(v, true);
      compact::end(record_, lp.inflated_lo(i, j), a, b, a);
      compact::end(record_, lp.inflated_hi(i, j), a, b, b);
    }
    binary(record_);
  }
}

void CertificateWriter::csncs(const AspectsResult& r) {
  line("csncs " + std::to_string(r.csnc_sizes.size()));
  std::vector<std::vector<int32_t>> members(r.csnc_sizes.size());
  for (int b = 0; b < r.boxes.size(); ++b)
    if (r.csnc[b] >= 0) members[r.csnc[b]].push_back(b);
  for (size_t k = 0; k < members.size(); ++k) {
    if (format_ == 3) {  // K, SIZE, then each id as a step beyond the one before
      record_.assign(1, char(0xC5));
      compact::varint(record_, k);
      compact::varint(record_, members[k].size());
      int64_t last = -1;
      for (int32_t b : members[k]) compact::varint(record_, uint64_t(b - last - 1)), last = b;
      binary(record_);
      continue;
    }
    put("csnc %zu %zu", k, members[k].size());
    for (int32_t b : members[k]) put(" %d", b);
    end_line();
  }
}

// Ends the compressed frame (if any), then syncs and renames the file into place.
void CertificateWriter::close() {
  FILE* out = f_;
  f_ = nullptr;
  if (std::fclose(out) != 0) file_.fail(errno);
  FILE* z = compressor_;
  compressor_ = nullptr;
  if (z && std::fclose(z) != 0) file_.fail(errno);
  file_.commit();
}

}  // namespace aspects
