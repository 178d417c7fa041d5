// LinkRecords (link.h): the certified links' numbers, in memory up to kSpillBytes, then in
// an unnamed temporary file written in large appends and read back through a cache.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include "link.h"

namespace aspects {

namespace {

[[noreturn]] void fail(const char* what) {
  throw std::runtime_error(std::string("link records: cannot ") + what + " a temporary file: " +
                           std::strerror(errno ? errno : EIO));
}

int unnamed_temporary() {
  const char* dir = std::getenv("TMPDIR");
  std::string name = std::string(dir && *dir ? dir : "/tmp") + "/aspects-links-XXXXXX";
  int fd = mkstemp(name.data());
  if (fd < 0) fail("create");
  unlink(name.c_str());  // gone with the process, whatever ends it
  return fd;
}

void write_all(int fd, const double* data, size_t count, size_t offset) {
  const char* p = reinterpret_cast<const char*>(data);
  size_t left = count * sizeof(double);
  while (left > 0) {
    ssize_t k = pwrite(fd, p, left, off_t(offset));
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) fail("write");
    p += k;
    left -= size_t(k);
    offset += size_t(k);
  }
}

void read_all(int fd, double* data, size_t count, size_t offset) {
  char* p = reinterpret_cast<char*>(data);
  size_t left = count * sizeof(double);
  while (left > 0) {
    ssize_t k = pread(fd, p, left, off_t(offset));
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) fail("read");
    p += k;
    left -= size_t(k);
    offset += size_t(k);
  }
}

}  // namespace

uint64_t LinkRecords::next_serial() {
  static std::atomic<uint64_t> next{1};
  return next++;
}

LinkRecords::LinkRecords(const LinkRecords& o) : n_(o.n_) {
  for (size_t i = 0; i < o.size(); ++i) add(o.record(i));
}

LinkRecords& LinkRecords::operator=(const LinkRecords& o) {
  if (this != &o) *this = LinkRecords(o);
  return *this;
}

LinkRecords::LinkRecords(LinkRecords&& o) noexcept
    : n_(o.n_), size_(o.size_), spilled_(o.spilled_), tail_(std::move(o.tail_)), fd_(o.fd_),
      serial_(next_serial()) {
  o.fd_ = -1;
  o.size_ = o.spilled_ = 0;
  o.tail_.clear();
  o.serial_ = next_serial();
}

LinkRecords& LinkRecords::operator=(LinkRecords&& o) noexcept {
  if (this != &o) {
    if (fd_ >= 0) close(fd_);
    n_ = o.n_;
    size_ = o.size_;
    spilled_ = o.spilled_;
    tail_ = std::move(o.tail_);
    fd_ = o.fd_;
    serial_ = next_serial();
    o.fd_ = -1;
    o.size_ = o.spilled_ = 0;
    o.tail_.clear();
    o.serial_ = next_serial();
  }
  return *this;
}

LinkRecords::~LinkRecords() {
  if (fd_ >= 0) close(fd_);
}

void LinkRecords::push(const LinkProof& p) {
  std::vector<double> rec;
  rec.reserve(stride());
  for (double x : p.witness) rec.push_back(x);
  for (const auto& q : p.existence.inflated) {
    rec.push_back(q.lo_down());  // exact: the iterate has double endpoints
    rec.push_back(q.hi_up());
  }
  for (double c : p.existence.C) rec.push_back(c);
  if (rec.size() != stride()) throw std::logic_error("link records: a proof of another size");
  add(rec.data());
}

void LinkRecords::add(const double* rec) {
  tail_.insert(tail_.end(), rec, rec + stride());
  ++size_;
  if (tail_.size() * sizeof(double) >= kSpillBytes) spill();
}

void LinkRecords::spill() {
  if (fd_ < 0) fd_ = unnamed_temporary();
  write_all(fd_, tail_.data(), tail_.size(), spilled_ * stride() * sizeof(double));
  spilled_ = size_;
  tail_.clear();
}

const double* LinkRecords::record(size_t i) const {
  if (i >= size_) throw std::out_of_range("link records: no record " + std::to_string(i));
  if (i >= spilled_) return &tail_[(i - spilled_) * stride()];
  // Windows of 1 MiB at multiples of their size: a sequential read (the certificate, the
  // index) reads each once, and a backward one does not reread a window per record. One
  // window per thread: a shared one, refilled by another thread under a reader, gives it
  // another window's numbers.
  struct Window {
    uint64_t serial = 0;
    size_t first = 0;
    std::vector<double> data;
  };
  thread_local Window w;
  const size_t per_cache = std::max<size_t>(1, (size_t(1) << 20) / (stride() * sizeof(double)));
  if (w.serial != serial_ || i < w.first || i - w.first >= w.data.size() / stride()) {
    w.serial = serial_;
    w.first = i - i % per_cache;
    const size_t count = std::min(per_cache, spilled_ - w.first);
    w.data.resize(count * stride());
    read_all(fd_, w.data.data(), w.data.size(), w.first * stride() * sizeof(double));
  }
  return &w.data[(i - w.first) * stride()];
}

}  // namespace aspects
