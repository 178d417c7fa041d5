// `aspects verify RESULT_DIR`: check_cert on the directory's certificate, then whether
// aspects.idx and summary.json are of the run that wrote it. What each part rests on:
// - the certificate: check_cert, the independent checker, verifies its claims;
// - the index and the summary: hash and count matches. Each records the certificate's
//   sha256(cert) as check_cert computes it and the model's hash; the summary records the
//   index's sha256 (the index checks its own checksum); their counts (solution boxes,
//   undecided boxes, links, CSNCs, eps; the summary's bound) are the certificate's, and
//   the summary says complete only if the certificate's tree is. The index's boxes, signs
//   and witnesses are not compared with the certificate's records one by one: a file
//   rewritten with its hashes recomputed would pass (the hashes are no signature).
#pragma once

#include <string>

namespace aspects {

struct VerifyOptions {
  std::string result_dir;
  int threads = 0;  // check_cert's --threads (0: its default)
  bool json = false;
};

enum class VerifyOutcome {
  Verified,     // check_cert VERIFIED, index and summary (when present) match it
  Unchecked,    // the same, but check_cert said UNCHECKED (the bound rests on a user factor)
  NotVerified,  // check_cert rejected the certificate, or a file does not match it
};

// Exit code: 0 verified, 3 unchecked, 1 not verified, 2 usage or input error (thrown: no
// directory or index, no certificate recorded, check_cert not found).
int run_verify(const VerifyOptions& opts);

}  // namespace aspects
