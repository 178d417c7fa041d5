// The result index `DIR/aspects.idx` that `aspects solve --out DIR` writes and that
// `aspects query` and `aspects path` read instead of re-solving: the model text, the
// solution boxes with their CSNC and determinant-factor signs, the pose part of the
// undecided boxes, and the certified links with their witness points (paper 4.1-4.3).
//
// It is a cache of the solver's output, not a certificate: query and path re-prove every
// command they print (Hansen-Sengupta at a point) and every link they cross (P3), and rely
// on the index only for P1's uniqueness inside a solution box. Binary, little-endian
// whatever the host, versioned; any anomaly is an IndexError naming the file.
//
// It names the certificate written with it (its file and sha256(cert), as check_cert
// prints it) and ends with a SHA-256 of its own bytes, which summary.json records: a
// damaged or edited index, or one beside another run's certificate or summary, is
// refused (results/result_files.h). The checksum is no signature: whoever rewrites the index
// can rewrite it too; `aspects verify` ties the files to the certificate check_cert checks.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace aspects {

struct AspectsResult;
struct Model;

constexpr uint32_t kResultIndexVersion = 2;
constexpr const char* kResultIndexName = "aspects.idx";

// A missing, truncated, malformed or other-version index; reported with exit code 2.
class IndexError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct IndexFactor {
  std::string origin;  // "det Fx", "diagonal of Fq", ...
  std::string text;
};

struct IndexSolutionBox {
  uint32_t id = 0;             // output box id, as in boxes.csv
  int32_t csnc = -1;           // component by decreasing size
  std::vector<double> lo, hi;  // every variable, model order (exact double endpoints)
  std::vector<int8_t> signs;   // one per factor: -1, +1 (0: may vanish)
};

struct IndexUndecidedBox {
  uint32_t id = 0;
  uint8_t kind = 0;            // UndecidedKind
  std::vector<double> lo, hi;  // pose variables only, pose order
};

struct IndexLink {
  uint32_t a = 0, b = 0;        // indices into ResultIndex::solutions (not box ids), a < b
  uint32_t shift_code = 0;      // NeighborPair::shift_code: box b + 2πk meets box a
  std::vector<double> witness;  // x̂ in box a's frame, pose order
  int shift(int v) const { return int((shift_code >> (2 * v)) & 3u) - 1; }
};

struct ResultIndex {
  std::string model_file;    // for messages
  std::string model_source;  // the model text, verbatim (parsed again by the reader)
  long precision_bits = 53;
  double tau = 1.01;
  double eps = 0.1;
  uint32_t nv = 0, n = 0;    // variables, equations (= pose = command variables)
  std::vector<IndexFactor> factors;
  uint32_t csnc_count = 0, filtered = 0;
  std::vector<IndexSolutionBox> solutions;  // by increasing id
  std::vector<IndexUndecidedBox> undecided;  // by increasing id
  std::vector<IndexLink> links;
  // The certificate written with the index: "aspects.cert" or "aspects.cert.zst" and its
  // sha256(cert), 64 hex digits; both empty without one (--no-cert).
  std::string certificate_file, certificate_sha256;
  // SHA-256 of the whole index file (64 hex digits, as sha256sum prints it; summary.json
  // records it), set when it is read.
  std::string sha256;
};

// The certificate of a run: set once it is written (empty: none).
struct CertificateId {
  std::string file, sha256;
};

// Every box of the index by increasing id, merging the two lists: f(true, i) for
// solutions[i], f(false, i) for undecided[i].
template <class F>
void for_each_box_by_id(const ResultIndex& idx, F&& f) {
  size_t i = 0, j = 0;
  while (i < idx.solutions.size() || j < idx.undecided.size()) {
    const bool solution = j == idx.undecided.size() ||
                          (i < idx.solutions.size() && idx.solutions[i].id < idx.undecided[j].id);
    if (solution) f(true, i++);
    else f(false, j++);
  }
}

// Gathers the index from a finished search. When the link proofs were not kept
// (--no-cert), the witnesses are recomputed with certify_link's rule (the midpoint of
// the inner intersection of the pose parts).
ResultIndex build_result_index(const Model& model, const AspectsResult& r, long precision_bits,
                               double tau, double eps, const std::string& model_file);

std::string encode_result_index(const ResultIndex& idx);
// Throws IndexError with `what` (e.g. the path) in the message.
ResultIndex decode_result_index(const std::string& bytes, const std::string& what);

// Atomic write (temporary name, then rename); returns the index's checksum.
std::string write_result_index(const std::string& path, const ResultIndex& idx);
// The same bytes as write_result_index(path, index) where index is build_result_index(...)
// with the certificate `certificate()` returns, without holding the index: the records are
// written as they are made, and `certificate` is called after the last one (it may wait
// for the certificate; an exception from it leaves no index). Returns the checksum.
std::string write_result_index(const std::string& path, const Model& model,
                               const AspectsResult& r, long precision_bits, double tau,
                               double eps, const std::string& model_file,
                               const std::function<CertificateId()>& certificate);
// Reads DIR/aspects.idx; IndexError when DIR or the file is missing or malformed.
ResultIndex read_result_index(const std::string& result_dir);

}  // namespace aspects
