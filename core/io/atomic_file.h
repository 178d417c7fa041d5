// Outputs are never left half-written: data goes to a temporary file in the target's
// directory, which is renamed over the target only once complete.
#pragma once

#include <cstdio>
#include <string>

namespace aspects {

// A file written under a temporary name and renamed over `path` by commit(). Destroyed
// without commit() (an exception on the way), it removes the temporary. Write failures
// are remembered and reported by commit(), with the first failure's reason.
class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path);  // throws std::runtime_error naming the path
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(const void* data, size_t n);
  void write(const std::string& s) { write(s.data(), s.size()); }
  // Flushes, fsyncs, closes and renames; then fsyncs the directory (best effort).
  // Throws std::runtime_error "cannot write PATH: REASON" on failure.
  void commit();

 private:
  void note_failure();  // keeps the first errno: "File too large", "No space left on device"
  std::string path_, tmp_;
  FILE* f_ = nullptr;
  int err_ = 0;
};

// The whole contents at once, through an AtomicFile.
void write_file_atomically(const std::string& path, const std::string& contents);

}  // namespace aspects
