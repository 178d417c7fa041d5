// Figures of a result (`aspects plot`, `aspects path --plot`): the boxes' pose parts are
// handed to the project's one plotting code, python/aspects/plotting.py, run by
// /usr/bin/python3 with matplotlib. An illustration only: nothing in it is a claim.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "loaded_result.h"

namespace aspects {

// plotting.py next to this program: the build tree's build/python/aspects/, or the
// installed P/lib/python3/dist-packages/aspects/ for P/bin/aspects. Empty when neither.
std::string find_plotting_script();

// Writes `png` (through a temporary name): the CSNCs and undecided boxes of `r`, and
// `path` on top when it is not null (what `aspects path --json` prints). Throws
// std::runtime_error when the figure cannot be written.
void write_result_plot(const LoadedResult& r, const nlohmann::json& path, const std::string& png);

}  // namespace aspects
