// How `aspects` reads its command line's numbers, and reports a command line it cannot
// parse: which subcommand's --help to read, and the subcommand or option the user probably
// meant.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace aspects {

// The numeric options are read as a pose's numbers are (results/number_text.h): a subnormal
// is kept; inf, nan and overflow are refused, naming the option (CLI11 prefixes its name).
extern const CLI::Validator kFiniteNumber;

// The closest of `names` to `typed` when it is close enough to be a typo (a prefix of it,
// or at most two edits away; ties: the first), else "".
std::string closest_name(const std::string& typed, const std::vector<std::string>& names);

// Prints the error of a failed `app.parse(argc, argv)` on stderr for program `program`:
// an unknown subcommand with the one meant, an unknown option with the one meant, and the
// --help of the subcommand the error is in. Returns the exit status, 2.
int report_parse_error(const CLI::App& app, const CLI::ParseError& e, int argc,
                       const char* const* argv);

}  // namespace aspects
