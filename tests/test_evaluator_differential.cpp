// Differential test of the two independent implementations: the solver's evaluator
// (core/) and check_cert's (certificates/checker/, namespace cc), the latter on MPFI and on
// its intervals of doubles. Both enclose the same
// ranges, so on every random box of every robot model their enclosures of each equation
// and each Jacobian entry must overlap; and both HC4 implementations must keep the
// surface points that robot_refs.h samples.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "../certificates/checker/checker.h"
#include "model/model_eval.h"

namespace {

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool overlap(const aspects::Interval& a, const cc::Ival& b) {  // b's ends are doubles
  return mpfr_cmp_d(&a.get()->left, b.hi()) <= 0 && mpfr_cmp_d(&a.get()->right, b.lo()) >= 0;
}

class Differential : public ::testing::TestWithParam<const char*> {};

}  // namespace

TEST_P(Differential, EnclosuresOverlapOnRandomBoxes) {
  aspects::set_working_precision(53);
  const std::string path = std::string(ASPECTS_ROBOTS_DIR) + "/" + GetParam();
  const std::string text = read(path);
  aspects::Model m = aspects::parse_model(text, path);
  cc::Model cm = cc::parse_model(text);  // syntax only: no interval of either kind
  for (bool doubles : {false, true}) {
    cc::set_interval_precision(53, doubles);
    ASSERT_EQ(cm.vars.size(), m.vars.size());
    ASSERT_EQ(cm.n(), m.n());
    aspects::ModelEvaluator ev(m);
    cc::Evaluator cev(cm);
    const int nv = int(m.vars.size()), n = m.n();
    aspects::Box dom = m.initial_box();
    std::mt19937 gen(2024);
    std::uniform_real_distribution<double> U(0, 1);
    std::vector<aspects::Interval> f;
    aspects::IMatrix jx, jq;
    std::vector<cc::Ival> cbox(nv);
    uint64_t all_dirs = (nv >= 64) ? ~0ull : ((1ull << nv) - 1);
    int compared = 0;
    for (int trial = 0; trial < 400; ++trial) {
      aspects::Box box(nv);
      for (int v = 0; v < nv; ++v) {
        double lo = dom[v].lo_down(), hi = dom[v].hi_up();
        double a = lo + (hi - lo) * U(gen), w = (hi - lo) * std::ldexp(U(gen), -int(U(gen) * 16));
        double blo = std::max(lo, a - w / 2), bhi = std::min(hi, a + w / 2);
        box[v].set_hull(blo, bhi);
        cbox[v].set(blo, bhi);
      }
      bool engine_ok = ev.equations(box, f) == aspects::EvalStatus::Defined &&
                       ev.jacobian_x(box, jx) == aspects::EvalStatus::Defined &&
                       ev.jacobian_q(box, jq) == aspects::EvalStatus::Defined;
      bool checker_ok = cev.eval_ad(cev.all_eqs, cbox.data(), all_dirs);
      if (!engine_ok || !checker_ok) continue;
      for (int i = 0; i < n; ++i) {
        ASSERT_TRUE(overlap(f[i], cev.val(cm.eqs[i])))
            << GetParam() << " trial " << trial << " equation " << i << ": " << f[i].str();
        for (int j = 0; j < n; ++j) {
          ASSERT_TRUE(overlap(jx(i, j), cev.der(cm.eqs[i], cm.pose[j])))
              << GetParam() << " trial " << trial << " Fx(" << i << "," << j << ")";
          ASSERT_TRUE(overlap(jq(i, j), cev.der(cm.eqs[i], cm.command[j])))
              << GetParam() << " trial " << trial << " Fq(" << i << "," << j << ")";
        }
      }
      ++compared;
    }
    EXPECT_GT(compared, 100);
  }
}

INSTANTIATE_TEST_SUITE_P(Robots, Differential,
                         ::testing::Values("prrp.robot", "rprpr.robot", "rrrrr.robot",
                                           "3rpr.robot", "3rrr_star.robot",
                                           "rrrrr_collisions.robot", "rrrrr_joint_limit.robot",
                                           "rrrrr_obstacle.robot"),
                         [](const auto& info) {
                           std::string s = info.param;
                           return s.substr(0, s.find('.'));
                         });
