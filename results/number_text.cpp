#include "results/number_text.h"

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdlib>

namespace aspects {

NumberText parse_number(const std::string& text, double& out) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(begin, &end);
  const bool range_error = errno == ERANGE;
  if (end == begin) return NumberText::Malformed;
  while (*end == ' ' || *end == '\t') ++end;
  if (*end != '\0') return NumberText::Malformed;
  if (!std::isfinite(x)) return NumberText::NotFinite;  // inf, nan, overflow (HUGE_VAL)
  // ERANGE on a finite result is underflow: x is the nearest double, subnormal or zero.
  if (range_error && std::fabs(x) > DBL_MIN) return NumberText::NotFinite;
  out = x;
  return NumberText::Finite;
}

std::string number_problem(NumberText outcome, const std::string& text) {
  switch (outcome) {
    case NumberText::Finite: return "";
    case NumberText::Malformed: return "'" + text + "' is not a number";
    case NumberText::NotFinite: return "'" + text + "' is not a finite number";
  }
  return "";
}

}  // namespace aspects
