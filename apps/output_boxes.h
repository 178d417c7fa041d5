// The per-box facts of a result (R = S ∪ U, in output order) as the writers of apps/ read
// them: each box's endpoints, whether it is a solution box, why it stayed undecided, and
// its sign vector. Reading them through these few functions keeps the writers independent
// of how AspectsResult stores its output boxes.
#pragma once

#include <cstddef>
#include <cstdint>

#include "generalized_aspects.h"

namespace aspects {

inline const BoxStore& output_boxes(const AspectsResult& r) { return r.boxes; }
inline int output_box_count(const AspectsResult& r) { return r.boxes.size(); }
inline bool is_solution_box(const AspectsResult& r, int b) { return r.certified[b] != 0; }
// Meaningful only for a box that is not a solution box.
inline UndecidedKind undecided_kind_of(const AspectsResult& r, int b) {
  return r.undecided_kind[b];
}
inline bool is_unexplored_box(const AspectsResult& r, int b) {
  return r.undecided_kind[b] == UndecidedKind::Unexplored;
}
// The box's sign of each of the result's factors (-1, 0, +1).
inline const int8_t* box_signs(const AspectsResult& r, int b) {
  return r.signs.data() + size_t(b) * r.factors.size();
}

}  // namespace aspects
