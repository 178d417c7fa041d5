// Outputs are never left half-written: data goes to a temporary file in the target's
// directory, which is renamed over the target only once complete.
#pragma once

#include <string>

namespace aspects {

// Throws std::runtime_error naming the path on failure.
void write_file_atomically(const std::string& path, const std::string& contents);

}  // namespace aspects
