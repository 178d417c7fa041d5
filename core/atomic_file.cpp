#include "atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace aspects {

void write_file_atomically(const std::string& path, const std::string& contents) {
  std::string tmp = path + ".tmp." + std::to_string(getpid());
  FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw std::runtime_error("cannot write " + tmp);
  int err = 0;  // the first failure's errno: "File too large", "No space left on device"
  auto check = [&](bool ok) {
    if (!ok && !err) err = errno ? errno : EIO;
  };
  check(std::fwrite(contents.data(), 1, contents.size(), f) == contents.size());
  check(std::fflush(f) == 0);
  check(fsync(fileno(f)) == 0);
  check(std::fclose(f) == 0);
  if (!err) check(std::rename(tmp.c_str(), path.c_str()) == 0);
  if (err) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write " + path + ": " + std::strerror(err));
  }
}

}  // namespace aspects
