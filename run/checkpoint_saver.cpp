#include "run/checkpoint_saver.h"

#include <cstdio>
#include <exception>

#include "aspects_version.h"

namespace aspects {

void CheckpointSaver::attach(const SolveOptions& o, const Model& model, AspectsConfig& cfg,
                             CertificateWriter* cert) {
  if (!(o.checkpoint > 0)) return;
  // The header names what the state belongs to; a resumed run is checked against it.
  header_.version = ASPECTS_VERSION_FULL;
  header_.model_sha256 = sha256_hex(model.source);
  header_.model_text = model.source;
  header_.model_file = o.model_path;
  header_.eps = o.eps;
  header_.tau = o.tau;
  header_.precision = o.prec;
  header_.bisect = o.bisect;
  header_.all_links = o.all_links;
  header_.no_cert = o.no_cert;
  header_.cert_format = o.cert_format;
  header_.defer_depth = cfg.defer_depth;
  header_.checkpoint_seconds = o.checkpoint;
  header_.nv = uint32_t(model.vars.size());
  cfg.checkpoint_seconds = o.checkpoint;
  cfg.checkpoint = [this, cert](const SearchState& st, const std::vector<uint8_t>& done) {
    save(st, done, cert);
  };
}

void CheckpointSaver::save(const SearchState& st, const std::vector<uint8_t>& done,
                           CertificateWriter* cert) {
  header_.p = uint32_t(st.top.boxes.factors());
  try {
    write_checkpoint(path_, header_, st, done, cert);
    last_ = CheckpointWrite::Written;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "aspects: %s; the previous checkpoint is kept\n", e.what());
    last_ = CheckpointWrite::Failed;
  }
}

}  // namespace aspects
