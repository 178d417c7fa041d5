// A value the user gave that makes no sense (an option, a pose): reported with exit code 2,
// by the command line (apps/aspects_main.cpp) and as ValueError by the Python module. Here,
// the lowest library that throws it, so that the run, the results and the front ends share it.
#pragma once

#include <stdexcept>

namespace aspects {

class UsageError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace aspects
