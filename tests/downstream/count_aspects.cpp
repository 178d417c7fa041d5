// Solves a robot model through the C++ API of the installed library and checks the counts.
// Usage: count_aspects MODEL [CSNCS LOWER_BOUND]   (default 4 4: PRRP's four aspects)
// Exit 0 when both counts are as expected, 1 when not, 2 on a usage or model error.
#include <aspects/generalized_aspects.h>
#include <aspects/numerics/interval.h>
#include <aspects/model/model.h>

#include <cstdio>
#include <cstdlib>
#include <exception>

int main(int argc, char** argv) {
  if (argc != 2 && argc != 4) {
    std::fprintf(stderr, "usage: count_aspects MODEL [CSNCS LOWER_BOUND]\n");
    return 2;
  }
  const long want_csncs = argc == 4 ? std::atol(argv[2]) : 4;
  const long want_bound = argc == 4 ? std::atol(argv[3]) : 4;
  try {
    aspects::set_working_precision(53);  // before any interval exists
    aspects::Model model = aspects::load_model(argv[1]);
    aspects::AspectsConfig config;
    config.eps = 0.1;
    config.threads = 2;
    aspects::AspectsResult r = aspects::compute_aspects(model, config);
    const long csncs = long(r.csnc_sizes.size()), bound = r.separation.lower_bound;
    std::printf("%s: %ld solution boxes, %ld CSNCs, lower bound %ld\n", model.name.c_str(),
                r.solutions, csncs, bound);
    if (csncs != want_csncs || bound != want_bound) {
      std::fprintf(stderr, "count_aspects: expected %ld CSNCs and lower bound %ld\n", want_csncs,
                   want_bound);
      return 1;
    }
    return 0;
  } catch (const aspects::ModelError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "count_aspects: %s\n", e.what());
    return 1;
  }
}
