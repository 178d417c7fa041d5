// An advisory lock on a directory: DIR/.lock, flock()ed while the holder lives. Two runs
// writing one result directory would mix their files; the second is refused at once.
#pragma once

#include <string>

namespace aspects {

enum class LockOutcome {
  Locked,       // this process holds the lock until the DirectoryLock is destroyed
  Held,         // another process (or another DirectoryLock of this one) holds it
  Unsupported,  // the filesystem has no flock (errno in error()): not locked
  Failed,       // DIR/.lock cannot be opened (errno in error())
};

class DirectoryLock {
 public:
  DirectoryLock() = default;
  ~DirectoryLock();
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

  // Tries once, without waiting; DIR must exist. The file stays when the lock is
  // released (removing it would let a third run lock a file no longer there).
  LockOutcome lock(const std::string& dir);
  int error() const { return err_; }
  static constexpr const char* kFileName = ".lock";

 private:
  int fd_ = -1;
  int err_ = 0;
};

}  // namespace aspects
