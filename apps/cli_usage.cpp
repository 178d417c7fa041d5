#include "cli_usage.h"

#include <algorithm>
#include <iostream>

#include "results/number_text.h"

namespace aspects {

const CLI::Validator kFiniteNumber(
    [](std::string& text) {
      double x = 0;
      return number_problem(parse_number(text, x), text);
    },
    "");

namespace {

// Edits from a to b: insertions, deletions, substitutions and swaps of two neighbours
// (optimal string alignment), so that "plto" is one edit from "plot", two from "path".
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1,
                          d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

std::string without_dashes(const std::string& s) {
  const size_t start = s.find_first_not_of('-');
  return start == std::string::npos ? std::string() : s.substr(start);
}

// The subcommand names of `app`, in the order of its --help.
std::vector<std::string> subcommand_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  return names;
}

// The long names (--eps) of the options of `app`.
std::vector<std::string> long_option_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options())
    for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

// The first argument that is not an option: the subcommand, when one is given (the main
// command takes no option with a value).
const char* first_word(int argc, const char* const* argv) {
  for (int i = 1; i < argc; ++i)
    if (argv[i][0] != '-') return argv[i];
  return nullptr;
}

}  // namespace

std::string closest_name(const std::string& typed, const std::vector<std::string>& names) {
  // Compared without their dashes: "--x" is not a typo of "--to".
  const std::string t = without_dashes(typed);
  if (t.empty()) return "";
  std::string best;
  size_t best_distance = 3;  // more than two edits is not a typo
  for (const std::string& n : names) {
    const std::string c = without_dashes(n);
    if (c == t) continue;
    // "solv" for solve, "epsilon" for eps: one is the other cut short.
    const size_t d = starts_with(c, t) || starts_with(t, c) ? 1 : edit_distance(t, c);
    if (d < best_distance && d < t.size()) {
      best = n;
      best_distance = d;
    }
  }
  return best;
}

int report_parse_error(const CLI::App& app, const CLI::ParseError& e, int argc,
                       const char* const* argv) {
  const std::string program = app.get_name();
  const std::vector<CLI::App*> chosen = app.get_subcommands();
  if (chosen.empty()) {
    const std::vector<std::string> names = subcommand_names(app);
    if (const char* word = first_word(argc, argv)) {
      std::cerr << program << ": unknown subcommand '" << word << "'";
      const std::string meant = closest_name(word, names);
      if (!meant.empty())
        std::cerr << "; did you mean `" << meant << "`?\n";
      else
        std::cerr << " (the subcommands: " << joined(names) << ")\n";
      std::cerr << "(run '" << program << " --help' for usage)\n";
      return 2;
    }
  }
  const CLI::App* where = chosen.empty() ? &app : chosen.front();
  std::cerr << program << ": " << e.what() << '\n';
  // An unknown option: the one of this subcommand it resembles.
  if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr) {
    const std::vector<std::string> names = long_option_names(*where);
    for (const std::string& extra : app.remaining(true)) {
      if (!starts_with(extra, "--")) continue;
      const std::string meant = closest_name(extra.substr(0, extra.find('=')), names);
      if (!meant.empty()) std::cerr << "did you mean " << meant << "?\n";
    }
  }
  const std::string help =
      program + (where == &app ? std::string() : " " + where->get_name()) + " --help";
  std::cerr << "(run '" << help << "' for usage)\n";
  return 2;
}

}  // namespace aspects
