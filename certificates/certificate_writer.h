// Writes the certificate of a run (format: certificates/FORMAT.md) while solving.
// The file is written under a temporary name and renamed by finish(); a run that
// stops early leaves nothing behind.
#pragma once

#include <cstdio>
#include <string>

#include "certificate_sink.h"
#include "generalized_aspects.h"

namespace aspects {

extern const char* const kToolVersion;

class CertificateWriter : public CertificateSink {
 public:
  CertificateWriter(const std::string& path, const Model& model, long precision, double tau,
                    double eps);
  ~CertificateWriter() override;
  CertificateWriter(const CertificateWriter&) = delete;
  CertificateWriter& operator=(const CertificateWriter&) = delete;

  void begin(const Box& domain, const std::vector<Factor>& factors) override;
  void contraction(int var, double lo, double hi) override;
  void split(int var, double at) override;
  void discard(const char* hint) override;
  void undecided(int32_t id, const int8_t* signs) override;
  void solution(int32_t id, const int8_t* signs, const SolutionProof& proof) override;

  // Links, CSNCs and claims; then closes and renames the file into place.
  void finish(const Model& model, const AspectsResult& result);
  long bytes() const { return bytes_; }

 private:
  void line(const std::string& s);
  void put(const char* fmt, ...);
  void real(double x);
  void interval(const Interval& x);
  void signs(const int8_t* s);
  void end_line();

  std::string path_, tmp_;
  FILE* f_ = nullptr;
  int p_ = 0, n_ = 0;
  long lines_ = 0, leaves_ = 0, bytes_ = 0;
  bool finished_ = false;
};

}  // namespace aspects
