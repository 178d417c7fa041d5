// ranks.cpp — speed layer: the processes of `mpirun -n P check_cert` (the MPI build,
// -DASPECTS_MPI=ON), which share the interval proofs of every batch (proof_batch.cpp).
// Every rank reads the whole certificate and applies every record rule itself; only the
// proofs are shared, and every rank judges each batch from the same per-proof results,
// so all ranks reach the same verdict, the one a single process reaches. Without MPI there
// is one rank and nothing to exchange.
#include <openssl/evp.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "speed.h"

#ifdef CHECK_CERT_MPI
#include <mpi.h>
#endif

namespace cc::ranks {

namespace {
int rank_ = 0, size_ = 1;


// SHA-256 of a file's bytes; "" if it cannot be read.
std::string file_sha256(const char* path) {
  FILE* f = std::fopen(path, "rb");
  if (!f) return "";
  EVP_MD_CTX* ctx = EVP_MD_CTX_new();
  EVP_DigestInit_ex(ctx, EVP_sha256(), nullptr);
  std::vector<char> buf(1 << 20);
  for (size_t got; (got = std::fread(buf.data(), 1, buf.size(), f)) > 0;)
    EVP_DigestUpdate(ctx, buf.data(), got);
  const bool ok = !std::ferror(f);
  std::fclose(f);
  unsigned char md[32];
  unsigned int len = 0;
  EVP_DigestFinal_ex(ctx, md, &len);
  EVP_MD_CTX_free(ctx);
  return ok ? std::string(reinterpret_cast<char*>(md), len) : "";
}
}  // namespace

int rank() { return rank_; }
int size() { return size_; }

std::string start(int* argc, char*** argv) {
#ifdef CHECK_CERT_MPI
  MPI_Init(argc, argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  return "";
#else
  (void)argc;
  (void)argv;
  // P copies of a whole check would each print the same line: a mistake, said before work.
  // Open MPI's and MPICH's launchers (and srun --mpi=pmi2) tell the job's size.
  int launched = 0;
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* v = std::getenv(name)) launched = std::max(launched, std::atoi(v));
  if (launched > 1)
    return "started by an MPI launcher, but this check_cert is built without MPI "
           "(configure with -DASPECTS_MPI=ON)";
  return "";
#endif
}

void stop() {
#ifdef CHECK_CERT_MPI
  MPI_Finalize();
#endif
}

void abort_all(const std::string& why) {
  std::fprintf(stderr, "check_cert: rank %d: %s\n", rank_, why.c_str());
#ifdef CHECK_CERT_MPI
  if (size_ > 1) MPI_Abort(MPI_COMM_WORLD, 1);
#endif
  std::exit(1);
}

// The ranks would deadlock, or disagree, on different bytes: every rank hashes its
// executable, its certificate and what shapes the check, and rank 0's digest must be all's.
int differing_rank(const std::string& cert, const std::string& options) {
  if (size_ == 1) return -1;
  std::string digest = file_sha256("/proc/self/exe") + file_sha256(cert.c_str()) + options;
  for (const char* name : {"CHECK_CERT_WORK_BASE", "CHECK_CERT_BATCH"})
    digest += std::string("\n") + (std::getenv(name) ? std::getenv(name) : "-");
  std::string ours = digest;
  broadcast(digest, 0);
  std::vector<uint64_t> differs(size_t(size_), 0);  // a sum of one flag a rank
  differs[size_t(rank_)] = ours != digest;
  sum(differs.data(), differs.size());
  const auto first = std::find(differs.begin(), differs.end(), 1);
  return first == differs.end() ? -1 : int(first - differs.begin());
}

void sum(uint64_t* v, size_t n) {
#ifdef CHECK_CERT_MPI
  if (size_ > 1)
    MPI_Allreduce(MPI_IN_PLACE, v, int(n), MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
#else
  (void)v, (void)n;
#endif
}

void broadcast(std::string& s, int root) {
#ifdef CHECK_CERT_MPI
  if (size_ == 1) return;
  uint64_t len = s.size();
  MPI_Bcast(&len, 1, MPI_UINT64_T, root, MPI_COMM_WORLD);
  s.resize(len);
  MPI_Bcast(s.data(), int(len), MPI_CHAR, root, MPI_COMM_WORLD);
#else
  (void)s, (void)root;
#endif
}

}  // namespace cc::ranks
