// The resumable state of `aspects solve --checkpoint SECONDS --out DIR`:
// DIR/checkpoint, read back by `aspects solve --resume DIR`.
//
// It holds the search's state (proofs/search_state.h: the top of the tree, the subtrees it
// deferred, the results of the finished ones) and the certificate records of every
// finished part, so that a resumed run ends with the same outputs as a run never stopped.
// A header names what the state belongs to (program version, SHA-256 of the model text,
// eps, precision, tau, bisector, links mode); a SHA-256 of the whole file ends it. It is
// written under a temporary name, fsynced and renamed: a crash leaves the previous one.
// Not a certificate: a damaged file is refused, and the final certificate of a resumed
// run is verified by check_cert like any other.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "search_state.h"

namespace aspects {

class CertificateWriter;

constexpr const char* kCheckpointName = "checkpoint";

struct CheckpointHeader {
  std::string version;       // the writer's ASPECTS_VERSION_FULL
  std::string model_sha256;  // of model_text
  std::string model_text;
  std::string model_file;    // as given on the command line; empty: the embedded robot
  double eps = 0, tau = 0;
  int64_t precision = 0;
  std::string bisect;
  bool all_links = false, no_cert = false;
  int32_t cert_format = 2;  // the certificate's format version (2 text, 3 binary records)
  int32_t defer_depth = 0;
  double checkpoint_seconds = 0;  // the interval; a resumed run keeps it unless given
  uint32_t nv = 0, p = 0;         // variables and sign factors (sizes of the records)
};

struct Checkpoint {
  CheckpointHeader header;
  SearchState state;
  std::string top_records;           // certificate records (empty with no_cert)
  // Format 3: where in top_records each deferred subtree's records go (byte offset, task).
  std::vector<std::pair<int64_t, int32_t>> top_marks;
  std::vector<std::string> records;  // per subtree; empty when not done
};

// A checkpoint that cannot be used: missing, damaged, or from another run. Exit 2.
class CheckpointError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string sha256_hex(const std::string& data);

// Writes `path` atomically. Only the parts marked in `done` (and the top, if done) are
// saved; their certificate records come from `cert` (null with no_cert). Throws
// std::runtime_error naming the file when it cannot be written (the previous one stays).
void write_checkpoint(const std::string& path, const CheckpointHeader& h, const SearchState& st,
                      const std::vector<uint8_t>& done, CertificateWriter* cert);

// Reads and checks (checksum first, then structure) a checkpoint; CheckpointError else.
// Sets the working precision to the checkpoint's (its boxes are intervals of it).
Checkpoint read_checkpoint(const std::string& path);

}  // namespace aspects
