// The files of a result directory (`aspects solve --out DIR`) and what ties them to one
// run: aspects.idx records the certificate's file name and sha256(cert), summary.json the
// certificate's, the model's and the index's hashes, and the certificate names its model's
// hash on its third line. A file of another run (a stale certificate, a summary of another
// eps) is named by mismatched_files; query and path refuse the directory then.
#pragma once

#include <string>
#include <vector>

#include "results/result_index.h"

namespace aspects {

constexpr const char* kCertificateName = "aspects.cert";
constexpr const char* kCompressedCertificateName = "aspects.cert.zst";
constexpr const char* kBoxesName = "boxes.csv";
constexpr const char* kSummaryName = "summary.json";

// The model hash a certificate records ("model BYTES SHA256", its third line), reading
// only its first lines (the start of a .zst decompressed); empty when there is none.
std::string certificate_model_sha256(const std::string& path);

// One message for each certificate file or summary.json in `dir` that is not of the run
// that wrote `idx` (empty: every one present is). Hash matches, cheap: the certificate's
// own sha256(cert) is computed by check_cert (`aspects verify`), not here.
std::vector<std::string> mismatched_files(const std::string& dir, const ResultIndex& idx);

// The first 16 hex digits of a hash, for messages ("(none)" when empty).
std::string short_hash(const std::string& hex);

}  // namespace aspects
