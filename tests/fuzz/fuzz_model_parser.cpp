// libFuzzer target: the model parser, and what `aspects info` and the first steps of
// `aspects solve` do with a parsed model. A ModelError is the expected outcome for bad
// input; any other exception, crash, sanitizer report or hang is a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "model/determinant_factors.h"
#include "model/model.h"
#include "model/model_eval.h"
#include "model/model_info.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static bool init = (aspects::set_working_precision(53), true);
  (void)init;
  std::string text(reinterpret_cast<const char*>(data), size);
  try {
    aspects::Model m = aspects::parse_model(text, "fuzz.robot");
    std::ostringstream out;
    aspects::print_model_info(m, out);
    if (m.n() <= 3) {
      aspects::determinant_factors(m);
      aspects::ModelEvaluator ev(m);
      aspects::Box box = m.initial_box();
      std::vector<aspects::Interval> f;
      ev.equations(box, f);
      for (int i = 0; i < m.n(); ++i) ev.hc4(i, box);
    }
  } catch (const aspects::ModelError&) {
  }
  return 0;
}
