// Writes the certificate of `aspects count` (certificates/FORMAT.md, "Count certificates"):
// the first cover's search tree as `aspects solve` writes it, then the count's records (how
// each box of the final cover came from the tree's output boxes, what shows each piece empty
// or nonempty, the adjacencies refuted) and its claims. The first cover's certificate is
// written by a CertificateWriter to `path + ".first-cover"` while it is solved; finish()
// keeps its header and tree, appends the count's records and renames the whole into place.
#pragma once

#include <memory>
#include <string>

#include "certificate_writer.h"
#include "counting/exact_count.h"

namespace aspects {

class CountCertificateWriter {
 public:
  CountCertificateWriter(const std::string& path, const Model& model, double eps);
  ~CountCertificateWriter();  // removes the first cover's file
  CountCertificateWriter(const CountCertificateWriter&) = delete;
  CountCertificateWriter& operator=(const CountCertificateWriter&) = delete;

  CertificateSink* first_cover() { return first_.get(); }
  // CountConfig::first_cover_done: finishes the first cover's certificate.
  static void first_cover_done(const AspectsResult& solved, void* self);
  // The count's records and claims; then the file is renamed into place.
  void finish(const Model& model, const CountResult& result);

 private:
  std::string path_, first_path_;
  const Model& model_;
  std::unique_ptr<CertificateWriter> first_;
  bool first_done_ = false;
};

}  // namespace aspects
