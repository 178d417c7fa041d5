// The compiled part of the Python package `aspects` (python/aspects/ wraps it).
#include "py_common.h"

namespace aspects::py {

pyb::object to_python(const nlohmann::json& j) {
  return pyb::module_::import("json").attr("loads")(j.dump());
}

}  // namespace aspects::py

PYBIND11_MODULE(_aspects, m) {
  m.doc() = "Certified generalized aspects of parallel robots (compiled core)";
  aspects::py::bind_errors(m);
  aspects::py::bind_model(m);
  aspects::py::bind_result(m);
  aspects::py::bind_solve(m);
}
