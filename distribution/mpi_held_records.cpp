#include "distribution/mpi_held_records.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace aspects {

namespace {

std::string held_path(int rank) {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/aspects-rank" + std::to_string(rank) + "-" +
         std::to_string(getpid()) + ".held";
}

}  // namespace

HeldRecords::HeldRecords(int rank) : path_(held_path(rank)) {
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd_ < 0) throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno));
  // Unnamed at once: a rank that is killed (the job aborted) leaves nothing behind.
  ::unlink(path_.c_str());
}

HeldRecords::~HeldRecords() { ::close(fd_); }

void HeldRecords::keep(int32_t task, const std::string& records) {
  uint64_t at;
  {
    std::lock_guard<std::mutex> g(lock_);
    at = size_;
    size_ += records.size();
  }
  for (size_t done = 0; done < records.size();) {
    const ssize_t k = ::pwrite(fd_, records.data() + done, records.size() - done, off_t(at + done));
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(k < 0 ? errno : ENOSPC));
    done += size_t(k);
  }
  std::lock_guard<std::mutex> g(lock_);  // readable once written
  where_[task] = {at, records.size()};
}

std::pair<uint64_t, uint64_t> HeldRecords::range(int32_t task) const {
  std::lock_guard<std::mutex> g(lock_);
  const auto it = where_.find(task);
  if (it == where_.end())
    throw std::runtime_error("rank 0 asked for the records of subtree " + std::to_string(task) +
                             ", which this rank did not search");
  return it->second;
}

void HeldRecords::append_to(int32_t task, std::string& out) const {
  const auto [offset, length] = range(task);
  const size_t at = out.size();
  out.resize(at + length);
  for (size_t done = 0; done < length;) {
    const ssize_t k = ::pread(fd_, &out[at + done], length - done, off_t(offset + done));
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) throw std::runtime_error("cannot read " + path_);
    done += size_t(k);
  }
}

}  // namespace aspects
