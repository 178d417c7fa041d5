// A run stopped after its search (paper 4.3-4.4 and 3.2 cut short) keeps only what it
// established, and check_cert verifies what it claims: each phase after the search asks
// the stop condition (proofs/pipeline/). The stop is requested as a phase ends, so the
// cut falls at a known place. Deliberate break that made it fail: SeparationPhase::finish
// returning the first pass's result after a stopped stream: the bound then counted every
// solution box apart (1,428 on RPRPR), and check_cert rejected the claim (exit 1).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>

#include "certificate_writer.h"
#include "generalized_aspects.h"

using namespace aspects;

namespace {

struct Stopped {
  AspectsResult r;
  int check_status;
};

// Solves RPRPR at eps 0.1 with its certificate, `setup` attaching what stops it, and runs
// check_cert on the certificate.
Stopped solve_stopped(const std::string& name,
                      const std::function<void(StopCondition&, AspectsConfig&)>& setup) {
  set_working_precision(53);
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rprpr.robot");
  const std::string path =
      (std::filesystem::temp_directory_path() / ("phase_stop_" + name + ".cert")).string();
  CertificateWriter cert(path, m, 53, 1.01, 0.1, false);
  StopCondition stop;
  AspectsConfig cfg;
  cfg.eps = 0.1;
  cfg.threads = 2;
  cfg.stop = &stop;
  cfg.certificate = &cert;
  setup(stop, cfg);
  Stopped s{compute_aspects(m, cfg), -1};
  cert.finish(m, s.r);
  const std::string cmd = std::string(CHECK_CERT) + " --quiet " + path + " > /dev/null";
  s.check_status = WEXITSTATUS(std::system(cmd.c_str()));
  std::filesystem::remove(path);
  return s;
}

// The same, requesting a stop of the whole run when `phase` ends.
Stopped solve_stopped_after(const std::string& phase, const std::string& name,
                            long max_boxes = 0) {
  return solve_stopped(name, [&](StopCondition& stop, AspectsConfig& cfg) {
    if (max_boxes > 0) stop.set_max_boxes(max_boxes);
    cfg.phase_done = [&stop, phase](const std::string& p, double) {
      if (p == phase) stop.request(StopReason::Signal);
    };
  });
}

AspectsResult solve_whole() {
  set_working_precision(53);
  Model m = load_model(std::string(ASPECTS_ROBOTS_DIR) + "/rprpr.robot");
  AspectsConfig cfg;
  cfg.eps = 0.1;
  cfg.threads = 2;
  return compute_aspects(m, cfg);
}

}  // namespace

TEST(PhaseStops, AfterTheSearchNoLinkNoBoundBeyondOneNoWitness) {
  const AspectsResult whole = solve_whole();
  ASSERT_TRUE(whole.complete());
  ASSERT_GT(whole.separation.lower_bound, 1);
  ASSERT_GT(whole.certified_links.size(), 0u);

  Stopped s = solve_stopped_after("merge", "merge");
  EXPECT_EQ(s.r.stopped_by, StopReason::Signal);
  EXPECT_EQ(s.r.stopped_in, "neighbourhood graph, separation and links");
  EXPECT_FALSE(s.r.complete());
  // The search itself was whole: the same boxes.
  EXPECT_EQ(s.r.boxes.size(), whole.boxes.size());
  EXPECT_EQ(s.r.unexplored, 0);
  // M was not streamed: no link, every solution box its own CSNC, the bound only what one
  // certified box of certain signs proves.
  EXPECT_EQ(s.r.neighbor_count, 0u);
  EXPECT_TRUE(s.r.certified_links.empty());
  EXPECT_EQ(long(s.r.csnc_sizes.size()), whole.solutions);
  EXPECT_EQ(s.r.separation.lower_bound, 1);
  EXPECT_TRUE(s.r.cuspidal.pose.empty());
  EXPECT_TRUE(s.r.cuspidal.command.empty());
  EXPECT_EQ(s.check_status, 0) << "check_cert must verify the partial result";
}

TEST(PhaseStops, AfterTheSeparationTheBoundStandsAndNoWitnessIsSought) {
  const AspectsResult whole = solve_whole();
  Stopped s = solve_stopped_after("components and separation", "separation");
  EXPECT_EQ(s.r.stopped_by, StopReason::Signal);
  EXPECT_EQ(s.r.stopped_in, "cuspidality");
  EXPECT_EQ(s.r.neighbor_count, whole.neighbor_count);
  EXPECT_EQ(s.r.certified_links.size(), whole.certified_links.size());
  EXPECT_EQ(s.r.csnc_sizes, whole.csnc_sizes);
  EXPECT_EQ(s.r.separation.lower_bound, whole.separation.lower_bound);
  EXPECT_TRUE(s.r.cuspidal.pose.empty());
  EXPECT_TRUE(s.r.cuspidal.command.empty());
  EXPECT_EQ(s.check_status, 0);
}

// A spent max-boxes budget stops the search alone: the phases after it run whole on the
// boxes it made.
TEST(PhaseStops, AMaxBoxesStopLeavesTheLaterPhasesWhole) {
  Stopped s = solve_stopped_after("", "max_boxes", 3000);
  EXPECT_EQ(s.r.stopped_by, StopReason::MaxBoxes);
  EXPECT_EQ(s.r.stopped_in, "search");
  ASSERT_GT(s.r.unexplored, 0);
  ASSERT_GT(s.r.solutions, 0);
  EXPECT_GT(s.r.neighbor_count, 0u);
  EXPECT_GT(s.r.certified_links.size(), 0u);
  EXPECT_LT(long(s.r.csnc_sizes.size()), s.r.solutions);
  EXPECT_EQ(s.check_status, 0);
}

// Ctrl-C (issue 50, item 9): the first interrupt stops the search, and the links, CSNCs,
// bound and witnesses are made on the boxes it made; a second one stops the phases too.
// Before the first interrupt stopped the search alone, a signal stopped every phase: no
// link, every solution box a CSNC of its own.
TEST(PhaseStops, AFirstInterruptStopsTheSearchAloneTheLaterPhasesRunWhole) {
  Stopped s = solve_stopped("interrupt_once", [](StopCondition& stop, AspectsConfig& cfg) {
    cfg.progress = [&stop](const SearchStats& st) {
      if (st.processed >= 3000 && stop.interrupts() == 0) stop.interrupt();
    };
  });
  EXPECT_EQ(s.r.stopped_by, StopReason::Signal);
  EXPECT_EQ(s.r.stopped_in, "search");
  EXPECT_EQ(s.r.run_stopped_in, "");
  ASSERT_GT(s.r.unexplored, 0);
  ASSERT_GT(s.r.solutions, 0);
  EXPECT_GT(s.r.neighbor_count, 0u);
  EXPECT_GT(s.r.certified_links.size(), 0u);
  EXPECT_LT(long(s.r.csnc_sizes.size()), s.r.solutions);
  EXPECT_GE(s.r.separation.lower_bound, 1);
  EXPECT_EQ(s.check_status, 0);
}

TEST(PhaseStops, ASecondInterruptStopsThePhasesAfterTheSearchToo) {
  Stopped s = solve_stopped("interrupt_twice", [](StopCondition& stop, AspectsConfig& cfg) {
    cfg.progress = [&stop](const SearchStats& st) {
      if (st.processed >= 3000 && stop.interrupts() == 0) {
        EXPECT_EQ(stop.interrupt(), StopScope::Search);
      }
    };
    cfg.phase_done = [&stop](const std::string& p, double) {
      if (p == "merge") {
        EXPECT_EQ(stop.interrupt(), StopScope::Run);
      }
    };
  });
  EXPECT_EQ(s.r.stopped_by, StopReason::Signal);
  EXPECT_EQ(s.r.stopped_in, "search");
  EXPECT_EQ(s.r.run_stopped_in, "neighbourhood graph, separation and links");
  ASSERT_GT(s.r.unexplored, 0);
  EXPECT_EQ(s.r.neighbor_count, 0u);
  EXPECT_TRUE(s.r.certified_links.empty());
  EXPECT_EQ(long(s.r.csnc_sizes.size()), s.r.solutions);
  EXPECT_EQ(s.r.separation.lower_bound, 1);
  EXPECT_EQ(s.check_status, 0);
}

// Once the search is over there is nothing left to stop but the cheap phases, which a
// first interrupt lets finish: the result is complete.
TEST(PhaseStops, AFirstInterruptAfterTheSearchLeavesTheResultComplete) {
  const AspectsResult whole = solve_whole();
  Stopped s = solve_stopped("interrupt_late", [](StopCondition& stop, AspectsConfig& cfg) {
    cfg.phase_done = [&stop](const std::string& p, double) {
      if (p == "merge") stop.interrupt();
    };
  });
  EXPECT_TRUE(s.r.complete());
  EXPECT_EQ(s.r.stopped_in, "");
  EXPECT_EQ(s.r.certified_links.size(), whole.certified_links.size());
  EXPECT_EQ(s.r.csnc_sizes, whole.csnc_sizes);
  EXPECT_EQ(s.r.separation.lower_bound, whole.separation.lower_bound);
  EXPECT_EQ(s.check_status, 0);
}
