#include "distribution/mpi_identity.h"

#include <cstdio>
#include <fstream>
#include <iterator>

#include "aspects_version.h"
#include "run/checkpoint.h"

namespace aspects {

namespace {

// The running executable's bytes; its version string when they cannot be read.
std::string executable_bytes() {
  std::ifstream in("/proc/self/exe", std::ios::binary);
  std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return in.bad() || b.empty() ? std::string(ASPECTS_VERSION_FULL) : b;
}

// One rank's record in the gather: a status byte (0, or its error's exit status), then
// the three hashes.
constexpr size_t kHash = 64;

}  // namespace

RunIdentity identity_of(const SolveOptions& o, const Model& m) {
  char opts[256];
  std::snprintf(opts, sizeof opts,
                "eps %a prec %ld tau %a bisect %s mpfi-only %d no-cert %d cert-format %d", o.eps,
                o.prec, o.tau, o.bisect.c_str(), int(o.mpfi_only), int(o.no_cert), o.cert_format);
  return {sha256_hex(executable_bytes()), sha256_hex(m.source), sha256_hex(opts)};
}

Agreement agree_on_run(MpiJob& job, const RunIdentity* mine, int failure_code) {
  std::string record(1 + 3 * kHash, '0');
  record[0] = char(mine ? 0 : failure_code);
  if (mine) record.replace(1, 3 * kHash, mine->binary + mine->model + mine->options);
  const std::vector<std::string> all = job.gather(record);
  Agreement a;
  if (job.rank() == 0) {
    auto differs = [&](int r, int field, RankAgreement outcome) {
      const std::string ours = all[0].substr(1 + field * kHash, kHash),
                        theirs = all[r].substr(1 + field * kHash, kHash);
      if (ours == theirs) return false;
      a = {outcome, r, 2, "rank 0 " + ours.substr(0, 16) + "..., rank " + std::to_string(r) +
                              " " + theirs.substr(0, 16) + "..."};
      return true;
    };
    if (all[0][0]) a = {RankAgreement::FailedOnRank0, 0, int(all[0][0]), ""};
    for (int r = 1; r < job.size() && a.outcome == RankAgreement::Agreed; ++r) {
      if (all[r][0]) a = {RankAgreement::FailedElsewhere, r, int(all[r][0]), ""};
      else if (differs(r, 0, RankAgreement::DifferentBinary)) break;
      else if (differs(r, 1, RankAgreement::DifferentModel)) break;
      else if (differs(r, 2, RankAgreement::DifferentOptions)) break;
    }
  }
  const std::vector<int> shared = job.broadcast({int(a.outcome), a.rank, a.exit_code});
  a.outcome = RankAgreement(shared[0]);
  a.rank = shared[1];
  a.exit_code = shared[2];
  return a;
}

std::string refusal_message(const Agreement& a) {
  const std::string r = "rank " + std::to_string(a.rank);
  switch (a.outcome) {
    case RankAgreement::FailedElsewhere:
      return r + " could not prepare the run (its error is above); nothing was computed";
    case RankAgreement::DifferentBinary:
      return r + " runs another aspects executable than rank 0 (SHA-256 of the executable: " +
             a.detail + "); every rank must run the same build. Refused before any work";
    case RankAgreement::DifferentModel:
      return r + " read another model text than rank 0 (SHA-256: " + a.detail +
             "); the model file must be the same on every node. Refused before any work";
    case RankAgreement::DifferentOptions:
      return r + " was given other options than rank 0 (eps, prec, tau, bisect, mpfi-only or "
                 "no-cert; SHA-256: " + a.detail + "). Refused before any work";
    default:
      return "";
  }
}

}  // namespace aspects
