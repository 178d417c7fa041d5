#include "io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace aspects {

AtomicFile::AtomicFile(const std::string& path)
    : path_(path), tmp_(path + ".tmp." + std::to_string(getpid())) {
  f_ = std::fopen(tmp_.c_str(), "wb");
  if (!f_) throw std::runtime_error("cannot write " + tmp_ + ": " + std::strerror(errno));
}

AtomicFile::~AtomicFile() {
  if (!f_) return;  // committed
  std::fclose(f_);
  std::remove(tmp_.c_str());
}

void AtomicFile::note_failure() {
  if (!err_) err_ = errno ? errno : EIO;
}

void AtomicFile::fail(int err) {
  if (!err_) err_ = err ? err : EIO;
}

void AtomicFile::write(const void* data, size_t n) {
  if (!err_ && std::fwrite(data, 1, n, f_) != n) note_failure();
}

void AtomicFile::commit() {
  if (!err_ && (std::fflush(f_) != 0 || std::ferror(f_))) note_failure();
  if (!err_ && fsync(fileno(f_)) != 0) note_failure();
  if (std::fclose(f_) != 0) note_failure();
  f_ = nullptr;
  if (!err_ && std::rename(tmp_.c_str(), path_.c_str()) != 0) note_failure();
  if (err_) {
    std::remove(tmp_.c_str());
    throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(err_));
  }
  // Makes the rename durable.
  std::string dir = std::filesystem::path(path_).parent_path().string();
  int fd = open(dir.empty() ? "." : dir.c_str(), O_RDONLY);
  if (fd >= 0) {
    fsync(fd);
    close(fd);
  }
}

void write_file_atomically(const std::string& path, const std::string& contents) {
  AtomicFile f(path);
  f.write(contents);
  f.commit();
}

}  // namespace aspects
