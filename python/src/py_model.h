// The Python Model: the model text and what a user reads of it (names, variables, domains,
// equations).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace aspects::py {

struct PyModel {
  std::string source, file, name, bisect;
  std::vector<std::string> variables, pose, command;
  // Model order, as `variables`: each domain's outward enclosure in doubles, and whether
  // the variable is periodic.
  std::vector<std::pair<double, double>> domains;
  std::vector<bool> periodic;
  // The statements' text as the parser normalised it (`aspects info` prints the same).
  std::vector<std::string> equations, factors, constraints;
  // Throw ModelError with FILE:LINE:COL.
  static PyModel parse(const std::string& text, const std::string& file);
  static PyModel load(const std::string& path);
};

}  // namespace aspects::py
