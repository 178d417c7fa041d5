// `aspects solve --checkpoint SECONDS` (by default kDefaultCheckpointSeconds with --out in a
// single process): saves the search's state into the output directory while it runs, and
// when it stops (run/checkpoint.h). A write that fails keeps the previous checkpoint and
// is reported; the run goes on, and only a stopped run whose last write failed is an error
// (it cannot be resumed).
#pragma once

#include <string>

#include "certificate_writer.h"
#include "generalized_aspects.h"
#include "model/model.h"
#include "run/checkpoint.h"
#include "run/solve_options.h"

namespace aspects {

// The outcome of the latest checkpoint write.
enum class CheckpointWrite { None, Written, Failed };

class CheckpointSaver {
 public:
  explicit CheckpointSaver(const SolveOptions& o) : path_(o.out_dir + "/" + kCheckpointName) {}
  CheckpointSaver(const CheckpointSaver&) = delete;
  CheckpointSaver& operator=(const CheckpointSaver&) = delete;

  // Makes the engine call save() every o.checkpoint seconds (nothing when not asked for);
  // the certificate's finished records are saved with the state.
  void attach(const SolveOptions& o, const Model& model, AspectsConfig& cfg,
              CertificateWriter* cert);
  void save(const SearchState& st, const std::vector<uint8_t>& done, CertificateWriter* cert);

  CheckpointWrite last_write() const { return last_; }
  const std::string& path() const { return path_; }

 private:
  CheckpointHeader header_;
  std::string path_;
  CheckpointWrite last_ = CheckpointWrite::None;
};

}  // namespace aspects
