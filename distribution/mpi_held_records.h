// The certificate records of the subtrees a rank of an MPI job searched, kept on that rank
// (one unnamed file of its TMPDIR, local disk) until rank 0 writes the certificate and fetches them
// subtree by subtree. Rank 0 then takes in each record once, as it writes it, instead of
// spooling every record while the search runs (distribution/mpi_subtrees.h).
#pragma once

#include <cstdint>
#include <mutex>
#include <string>
#include <unordered_map>
#include <utility>

namespace aspects {

class HeldRecords {
 public:
  explicit HeldRecords(int rank);
  ~HeldRecords();
  HeldRecords(const HeldRecords&) = delete;
  HeldRecords& operator=(const HeldRecords&) = delete;

  // Keeps subtree `task`'s records (from any thread).
  void keep(int32_t task, const std::string& records);
  // The size of its records; throws if this rank holds none for it.
  uint64_t size(int32_t task) const { return range(task).second; }
  // Appends its records to `out` (the message that takes them: no copy in between).
  void append_to(int32_t task, std::string& out) const;

 private:
  std::pair<uint64_t, uint64_t> range(int32_t task) const;  // offset, length; throws

  std::string path_;
  int fd_ = -1;
  mutable std::mutex lock_;
  uint64_t size_ = 0;
  std::unordered_map<int32_t, std::pair<uint64_t, uint64_t>> where_;  // offset, length
};

}  // namespace aspects
