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
  // The temporary's stream, for a writer that formats into it or layers another stream
  // over it (a compressor). Its write errors are seen by commit(); it stays open until then.
  FILE* stream() const { return f_; }
  const std::string& temporary_path() const { return tmp_; }
  // A failure the caller found on a stream layered over stream() (errno's value; the first
  // failure is the one reported): commit() then fails.
  void fail(int err);
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
