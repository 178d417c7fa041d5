#include "io/directory_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>

namespace aspects {

DirectoryLock::~DirectoryLock() {
  if (fd_ >= 0) close(fd_);  // releases the lock
}

LockOutcome DirectoryLock::lock(const std::string& dir) {
  const std::string path = dir + "/" + kFileName;
  const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) {
    err_ = errno;
    return LockOutcome::Failed;
  }
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    err_ = errno;
    close(fd);
    return err_ == EWOULDBLOCK ? LockOutcome::Held
           : (err_ == ENOLCK || err_ == EOPNOTSUPP || err_ == ENOSYS) ? LockOutcome::Unsupported
                                                                      : LockOutcome::Failed;
  }
  fd_ = fd;
  return LockOutcome::Locked;
}

}  // namespace aspects
