// Numbers the user types: a pose's coordinates, and the numeric options of the command
// line (--eps, --tau, ...). One parser, so every place accepts and refuses the same texts.
#pragma once

#include <string>

namespace aspects {

enum class NumberText {
  Finite,     // a finite double: the one nearest the text
  Malformed,  // not a number at all, or followed by other characters
  NotFinite,  // inf, nan, or beyond the range of doubles (overflow)
};

// Decimal or hexadecimal (strtod's syntax, surrounding blanks allowed). A value below the
// normal range is kept as the nearest double: a subnormal, or zero below half the least
// subnormal (strtod reports ERANGE for it, which is no error here).
NumberText parse_number(const std::string& text, double& out);

// "'TEXT' is not a number" or "'TEXT' is not a finite number"; empty for Finite.
std::string number_problem(NumberText outcome, const std::string& text);

}  // namespace aspects
