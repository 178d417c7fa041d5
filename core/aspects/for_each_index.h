// A parallel loop handed to core/ by its caller, so that core/ need not link a threading
// library: the engine passes one that runs in its TBB arena.
#pragma once

#include <cstdint>
#include <functional>

namespace aspects {

// Runs body(i) for every i < n, in any order and possibly at once. Callers give bodies
// that share nothing but read-only data, so that results do not depend on the order.
using ForEachIndex = std::function<void(int n, const std::function<void(int32_t)>& body)>;

inline void serial_for_each(int n, const std::function<void(int32_t)>& body) {
  for (int32_t i = 0; i < n; ++i) body(i);
}

}  // namespace aspects
