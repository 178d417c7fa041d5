// Shared by the binding files of the Python module `aspects._aspects`: the result a
// Python `Result` wraps, and the exceptions the module raises.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "results/loaded_result.h"

namespace aspects::py {

namespace pyb = pybind11;

// A solved or loaded result: the index (solution boxes, undecided pose parts, links) with
// its model, the summary.json contents, and the directory holding it (empty: in memory).
struct PyResult {
  std::shared_ptr<LoadedResult> loaded;
  nlohmann::json summary;
  std::string dir;
};

// nlohmann::json -> a Python object (through the json module: one code path, exact doubles).
pyb::object to_python(const nlohmann::json& j);

void bind_errors(pyb::module_& m);
void bind_model(pyb::module_& m);
void bind_solve(pyb::module_& m);
void bind_result(pyb::module_& m);
void bind_count(pyb::module_& m);

}  // namespace aspects::py
