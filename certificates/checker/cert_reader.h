// cert_reader.h — strict, streaming reader of the certificate's lexical layer (FORMAT.md,
// "Lexical rules"): one record per line, single-space separated fields, canonical decimal
// integers and canonical `%a` hexadecimal reals. It hashes every byte it consumes
// (SHA-256 of the whole file) and numbers lines for error messages. Anything that does
// not follow the rules is a Malformed error (exit 2); failed verifications are Rejected
// errors (exit 1), thrown by the other modules with the record they concern.
#pragma once

#include <openssl/evp.h>

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace cc {

struct CertError : std::runtime_error {
  bool malformed;  // true: exit 2; false: exit 1 (REJECTED)
  long record;
  CertError(bool m, long r, const std::string& why)
      : std::runtime_error(why), malformed(m), record(r) {}
};
[[noreturn]] void malformed(long record, const std::string& why);
[[noreturn]] void rejected(long record, const std::string& why);

std::string sha256_hex(const std::string& bytes);

class LineReader {
 public:
  explicit LineReader(FILE* f);  // takes ownership of f
  ~LineReader();
  // Reads the next record and splits it into fields; checks the lexical rules.
  LineReader& next();
  // next(), then requires the leading fields == words and `extra` further fields.
  LineReader& expect(const std::vector<const char*>& words, size_t extra);
  // The same test on the record read last.
  LineReader& require(const std::vector<const char*>& words, size_t extra);
  void count(size_t k);  // the record read last has k fields
  std::string_view kind() const { return fields_[0]; }
  size_t size() const { return fields_.size(); }
  // The fields of the record read last, left to right after its leading words.
  std::string_view word();
  int64_t integer();
  double real();
  std::vector<double> reals(size_t k);
  // k intervals LO HI (2k reals, all parsed before any LO <= HI is checked).
  std::vector<double> intervals(size_t k);
  // Reads exactly `n` raw bytes (the embedded model text) and counts its lines.
  std::string raw(size_t n);
  void expect_eof();                         // nothing may follow the last record
  long record() const { return line_; }      // number of the record read last
  uint64_t bytes() const { return bytes_; }  // bytes read so far
  std::string file_sha256();                 // after expect_eof

 private:
  FILE* f_ = nullptr;
  EVP_MD_CTX* md_ = nullptr;
  char* line_buf_ = nullptr;
  size_t line_cap_ = 0;
  long line_ = 0;
  uint64_t bytes_ = 0;
  std::vector<std::string_view> fields_;  // views into line_buf_, valid until the next read
  size_t pos_ = 0;                        // the next field word() returns
};

struct CheckOptions {
  bool quiet = false;          // no statistics on stderr
  bool trust_factors = false;  // accept a bound that rests on user-supplied factors
};

// What a check found; `verdict` is VERIFIED, UNCHECKED, REJECTED or MALFORMED.
struct Verdict {
  std::string verdict, reason, cert_sha, model_sha, robot;
  long record = 0;  // the record a rejection concerns
  long solutions = 0, undecided = 0, links = 0, csncs = 0;
  long unexplored = 0;  // N records: a stopped run's cells never searched (complete=no)
  long cuspidal = 0, cuspidal_csncs = 0;  // verified W records; CSNCs with one
  long assembly = 0;                      // verified V records
  long claimed = -1, recomputed = -1, checked = -1;  // bounds: claimed, all factors, no user
  bool user_factors = false;
};

// Exit statuses of check_cert.
enum Exit { kVerified = 0, kRejected = 1, kMalformed = 2, kUserFactors = 3 };

// The whole check (main.cpp): reads a certificate from f (closed on return) and returns the
// exit status, with what it found in `out`.
int check_certificate(FILE* f, const CheckOptions& o, Verdict& out);

// A canonical decimal integer (FORMAT.md); `rec` is the record named in the error.
int64_t parse_int(std::string_view s, long rec);

}  // namespace cc
