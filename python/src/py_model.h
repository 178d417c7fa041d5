// The Python Model: the model text and what a user reads of it (names, variables).
#pragma once

#include <string>
#include <vector>

namespace aspects::py {

struct PyModel {
  std::string source, file, name, bisect;
  std::vector<std::string> variables, pose, command;
  // Throw ModelError with FILE:LINE:COL.
  static PyModel parse(const std::string& text, const std::string& file);
  static PyModel load(const std::string& path);
};

}  // namespace aspects::py
