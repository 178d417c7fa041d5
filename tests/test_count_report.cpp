// What `aspects count` prints after its first line (run/count_report.h): the factors, named by
// their origin when their text is long, and the lower bound's regions.
#include <gtest/gtest.h>

#include <sstream>

#include "model/model.h"
#include "run/count_report.h"

using namespace aspects;

namespace {

Model circle() {
  return parse_model("robot c\npose x in [-2, 2]\ncommand q in [-2, 2]\nequation x^2 + q^2 = 1\n",
                     "c.robot");
}

CountResult two_regions(bool exact) {
  CountResult r;
  r.bounds.lower = 2;
  r.bounds.upper = exact ? 2 : -1;
  r.factor_text = {"2*x (det Fx)", std::string(90, 'q') + " (diagonal Fq, entry (1,1))"};
  r.factor_origin = {"det Fx", "diagonal Fq, entry (1,1)"};
  CountRegion a;
  a.cls = 1;  // det Fx > 0, Fq's entry < 0
  a.boxes = 3;
  a.lo = {0.5, -1};
  a.hi = {1, 0};
  a.pose_volume = 0.75;
  r.regions = {a, a};
  r.regions[1].cls = 2;
  r.regions[1].boxes = 1;
  return r;
}

std::string details(const CountResult& r) {
  std::ostringstream out;
  print_count_details(out, circle(), r, 0.5);
  return out.str();
}

}  // namespace

TEST(CountReport, ALongFactorIsNamedByItsOriginAndItsLength) {
  const std::string s = details(two_regions(true));
  EXPECT_NE(s.find("sign classes over:  2*x (det Fx)  diagonal Fq, entry (1,1) [90 characters; "
                   "--json gives it]\n"),
            std::string::npos)
      << s;
}

TEST(CountReport, RegionsAreTheAspectsOnlyWhenTheCountIsExact) {
  const std::string exact = details(two_regions(true));
  EXPECT_NE(exact.find("the aspects, largest first"), std::string::npos) << exact;
  EXPECT_NE(exact.find("  1. +-  3 boxes  x in [0.5, 1]  volume 0.75\n"), std::string::npos)
      << exact;
  EXPECT_NE(exact.find("  2. -+  1 box  x in [0.5, 1]  volume 0.75\n"), std::string::npos)
      << exact;
  const std::string open = details(two_regions(false));
  EXPECT_EQ(open.find("the aspects"), std::string::npos) << open;
  EXPECT_NE(open.find("the regions of the lower bound (each holds at least one aspect)"),
            std::string::npos)
      << open;
}

TEST(CountReport, JsonListsEveryRegionWithEveryVariable) {
  const nlohmann::json j = count_json(circle(), two_regions(false), 0.5);
  ASSERT_EQ(j["regions"].size(), 2u);
  EXPECT_EQ(j["regions"][0]["class"], "+-");
  EXPECT_EQ(j["regions"][0]["lo"], nlohmann::json({0.5, -1}));
  EXPECT_EQ(j["regions"][1]["boxes"], 1);
  EXPECT_EQ(j["factors"][1], std::string(90, 'q') + " (diagonal Fq, entry (1,1))");
}
