// Writes the certificate of a run (format: certificates/FORMAT.md) while solving.
// The file is an AtomicFile, renamed into place by finish(); a run that stops early
// leaves nothing behind.
#pragma once

#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "certificate_sink.h"
#include "compact_records.h"
#include "generalized_aspects.h"
#include "io/atomic_file.h"

namespace aspects {

extern const char* const kToolVersion;

// Tree records of one subtree, buffered in a temporary file until the writer splices
// the subtrees in depth-first order: version 2 text (a deferred subtree is a line '@TASK',
// output ids local to the subtree), or, with a coder, format 3's binary records (implied
// ids; deferred subtrees kept by byte offset in marks(); the file ends with two u64, little
// endian: its records and its leaves).
class TreeRecordFile : public TreeSink {
 public:
  TreeRecordFile(const std::string& path, int factors, int n,
                 std::unique_ptr<CompactTree> compact = nullptr);
  // Records already written, bytes [begin, end) of another's file (CertificateWriter's
  // spool of restored parts): read, never written nor removed.
  TreeRecordFile(const std::string& path, long begin, long end, bool binary);
  // Records already written, held in memory (fetched from another process as the
  // certificate is spliced: CertificateWriter::restore_later).
  TreeRecordFile(std::string records, bool binary);
  ~TreeRecordFile() override;
  TreeRecordFile(const TreeRecordFile&) = delete;
  TreeRecordFile& operator=(const TreeRecordFile&) = delete;

  void contraction(int var, double lo, double hi) override;
  void split(int var, double at) override;
  void discard(const char* hint) override;
  void undecided(int32_t id, const int8_t* signs) override;
  void unexplored(int32_t id, const int8_t* signs) override;
  void solution(int32_t id, const int8_t* signs, const SolutionProof& proof) override;
  void deferred(int32_t task) override;
  void finished() override { close(); }

  const std::string& path() const { return path_; }
  // Where its records are in path(): [begin, end); end -1: to the end of the file.
  long begin() const { return begin_; }
  long end() const { return end_; }
  bool shared() const { return end_ >= 0; }
  bool in_memory() const { return in_memory_; }
  std::string& memory() { return memory_; }
  void close();  // flushes (format 3: after the trailer); the file can then be read back
  // Format 3: the file holds binary records (a shared range: with their trailer).
  bool binary() const { return binary_; }
  struct Mark {
    long offset;  // bytes of this file's records before the deferred subtree's place
    int32_t task;
  };
  const std::vector<Mark>& marks() const { return marks_; }
  void set_marks(std::vector<Mark> marks) { marks_ = std::move(marks); }

 private:
  void signs(const int8_t* s);
  void emit();  // format 3: writes record_, one record
  std::string path_;
  FILE* f_ = nullptr;
  long begin_ = 0, end_ = -1;
  int p_ = 0, n_ = 0;
  std::unique_ptr<CompactTree> compact_;
  bool binary_ = false, trailer_ = false;
  std::string record_;
  uint64_t records_ = 0, leaves_ = 0;
  std::vector<Mark> marks_;
  bool in_memory_ = false;
  std::string memory_;
};

// The format 3 coder of a subtree whose root cell is `root`.
std::unique_ptr<CompactTree> compact_tree(const Box& root, const Model& model, int factors);

class CertificateWriter : public CertificateSink {
 public:
  // compress: the file is one zstd frame (certificates/compressed_output.h). format: 2
  // (text) or 3 (the bulky records in binary, certificates/compact_records.h).
  CertificateWriter(const std::string& path, const Model& model, long precision, double tau,
                    double eps, bool compress = false, int format = 2);
  ~CertificateWriter() override;
  CertificateWriter(const CertificateWriter&) = delete;
  CertificateWriter& operator=(const CertificateWriter&) = delete;

  void begin(const Box& domain, const std::vector<Factor>& factors) override;
  TreeSink* top() override { return top_.get(); }
  TreeSink* subtree(int32_t task, const Box& root) override;

  // Checkpoints (run/checkpoint.*): the records of a finished part (task -1: the top),
  // and a finished part's records put back before a resumed search (instead of searching
  // it: then neither top() nor subtree(task) is called for it).
  std::string records(int32_t task);
  // Format 3: where its deferred subtrees' records go in records(task).
  std::vector<TreeRecordFile::Mark> marks(int32_t task) const;
  void restore(int32_t task, const std::string& records) override { restore(task, records, {}); }
  void restore(int32_t task, const std::string& records, std::vector<TreeRecordFile::Mark> marks);
  // Fetched as the certificate is spliced, and read from memory. Not with
  // checkpoints: records(task) refuses a subtree whose records are still held elsewhere.
  void restore_later(int32_t task, std::function<std::string()> fetch) override;

  // Links, CSNCs and claims; then closes and renames the file into place.
  void finish(const Model& model, const AspectsResult& result);
  long bytes() const { return bytes_; }  // of the text, before any compression
  // After finish(): SHA-256 of the certificate's bytes before any compression (64 hex
  // digits), the sha256(cert) that check_cert prints.
  const std::string& sha256() const { return sha256_; }

 private:
  void line(const std::string& s);
  void put(const char* fmt, ...);
  void real(double x);
  void interval(const Interval& x);
  void end_line();
  struct Splicing;
  void splice(TreeRecordFile& top);
  Splicing open_splicing(TreeRecordFile& stream);
  TreeRecordFile* copy_until_subtree(Splicing& s);
  void end_splicing(Splicing& s);
  TreeRecordFile& task_records(int32_t task);  // fetched first if held elsewhere
  bool held(int32_t task) const {  // restore_later's, not yet fetched
    return task >= 0 && size_t(task) < held_.size() && held_[task];
  }
  FILE* open_records(TreeRecordFile& stream, long* size);  // at its first byte
  void spliced(TreeRecordFile& stream);  // frees its disk space or memory
  void binary(const std::string& record);  // one format 3 record
  void links(const Model& model, const AspectsResult& r);
  void csncs(const AspectsResult& r);
  void close();

  static constexpr long kBuffer = 1 << 20;
  // f_'s stdio buffer, this writer's own (two writers may coexist); before file_, so that
  // it outlives file_'s closing of an unfinished certificate.
  std::unique_ptr<char[]> buffer_;
  AtomicFile file_;
  FILE* f_ = nullptr;  // the hashing stream over compressor_ or file_'s stream
  FILE* compressor_ = nullptr;  // with compression: layered over file_'s stream
  std::string sha256_;
  std::unique_ptr<TreeRecordFile> top_;
  std::vector<std::unique_ptr<TreeRecordFile>> tasks_;
  std::vector<std::function<std::string()>> held_;  // per task: restore_later's fetch
  // Restored parts' records, one after another in one file: an MPI job's rank 0 restores
  // a part for each subtree another rank searched, and a file each cost 150 µs to create
  // on ext4 (65,536 subtrees on 256 ranks), more on a parallel filesystem.
  FILE* spool_ = nullptr;
  long spool_size_ = 0;
  int p_ = 0, n_ = 0;
  long lines_ = 0, leaves_ = 0, bytes_ = 0;
  int format_ = 2;
  const Model& model_;
  std::string record_;  // scratch: one binary record
  std::vector<char> copy_buffer_;  // scratch of splice: format 3's records
  char* line_ = nullptr;  // scratch of splice (getline's): one format 2 record
  size_t line_size_ = 0;
};

}  // namespace aspects
