// The certificate writer's parts from elsewhere: records held by the process that searched
// a subtree (an MPI rank: distribution/mpi_held_records.h) and fetched as the certificate is written
// give the certificate of a single process, byte for byte; a checkpoint cannot take them
// (CertificateWriter::records refuses). Another process is stood in for by a thread, as in
// test_generalized_aspects.cpp, so that this runs in the default build, without MPI. And
// two writers at once (two solves in one process, as the Python module allows).
#include <gtest/gtest.h>

#include <mpfr.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <thread>

#include "certificate_writer.h"
#include "generalized_aspects.h"
#include "model/determinant_factors.h"
#include "pipeline/remote_subtrees.h"
#include "pipeline/search_phase.h"

using namespace aspects;

namespace {

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string temp(const std::string& name) {
  return (std::filesystem::temp_directory_path() / (std::to_string(getpid()) + name)).string();
}

// Searches every subtree it claims with its own records file, and returns every other
// one's records held: fetch_records hands them over when the writer asks.
class HoldingRemote : public RemoteSubtrees {
 public:
  HoldingRemote(const AspectsConfig& c, int format) : config_(c), format_(format) {}
  void serve(SubtreeQueue& queue, const std::vector<DeferredSubtree>& deferred, int,
             const std::function<bool()>&, const Returned& returned,
             bool records_may_wait) override {
    set_working_precision(53);
    Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rprpr.robot");
    const std::vector<Factor> factors = determinant_factors(m);
    const int p = int(factors.size());
    for (int32_t k; (k = queue.claim()) >= 0;) {
      SearchPart part;
      std::string records;
      {
        TreeRecordFile sink(temp("held_records_test.t"), p, m.n(),
                            format_ == 3 ? compact_tree(deferred[k].box, m, p) : nullptr);
        search_subtree(m, config_, factors, deferred[k], part, &sink);
        records = read_all(sink.path());
      }
      ReturnedPart back;
      back.part = std::move(part);
      back.record_bytes = records.size();
      if (records_may_wait && k % 2 == 1) {
        ++held;
        back.fetch_records = [this, records] {
          ++fetched;
          return records;
        };
        records.clear();
      }
      returned(k, PartOutcome::Complete, std::move(back), std::move(records));
    }
    mpfr_free_cache();  // this thread ends here (MPFR's caches are per thread)
  }
  int held = 0, fetched = 0;

 private:
  AspectsConfig config_;
  int format_;
};

std::string certificate(int format, HoldingRemote* remote, const std::string& name) {
  set_working_precision(53);
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rprpr.robot");
  const std::string path = temp(name);
  CertificateWriter cert(path, m, 53, 1.01, 0.1, false, format);
  AspectsConfig cfg;
  cfg.eps = 0.1;
  cfg.threads = 2;
  cfg.certificate = &cert;
  cfg.grid_records = format == 3;
  cfg.remote = remote;
  AspectsResult r = compute_aspects(m, cfg);
  cert.finish(m, r);
  std::string bytes = read_all(path);
  std::filesystem::remove(path);
  return bytes;
}

}  // namespace

TEST(HeldRecords, FetchedAsTheCertificateIsWrittenGiveTheSameCertificate) {
  // Seen failing with the held records put back a byte short (CertificateWriter::
  // task_records): the certificates differ.
  for (int format : {2, 3}) {
    const std::string alone = certificate(format, nullptr, "held_records_alone.cert");
    AspectsConfig search;
    search.eps = 0.1;
    search.grid_records = format == 3;
    HoldingRemote remote(search, format);
    const std::string shared = certificate(format, &remote, "held_records_shared.cert");
    EXPECT_GT(remote.held, 0) << format;
    EXPECT_EQ(remote.fetched, remote.held) << format;  // each once
    EXPECT_GT(alone.size(), 100000u) << format;
    EXPECT_TRUE(alone == shared) << "format " << format << ": the certificates differ";
  }
}

TEST(HeldRecords, ACheckpointCannotTakeRecordsHeldElsewhere) {
  set_working_precision(53);
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rprpr.robot");
  const std::string path = temp("held_records_refused.cert");
  {
    CertificateWriter cert(path, m, 53, 1.01, 0.1, false);
    int fetched = 0;
    cert.restore_later(0, [&] {
      ++fetched;
      return std::string();
    });
    EXPECT_THROW(cert.records(0), std::logic_error);
    EXPECT_EQ(fetched, 0);
  }
  std::filesystem::remove(path);
}

TEST(HeldRecords, TwoWritersAtOnceWriteTheirOwnCertificates) {
  // Seen failing with the writers' stdio buffer a static array shared by both.
  const std::string alone = certificate(2, nullptr, "two_writers_alone.cert");
  std::string a, b;
  std::thread other([&] {
    a = certificate(2, nullptr, "two_writers_a.cert");
    mpfr_free_cache();  // this thread ends here (MPFR's caches are per thread)
  });
  b = certificate(2, nullptr, "two_writers_b.cert");
  other.join();
  EXPECT_TRUE(a == alone) << "the first writer's certificate differs";
  EXPECT_TRUE(b == alone) << "the second writer's certificate differs";
}
