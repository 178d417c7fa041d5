// Prune's part of Algorithm 1 (paper 4.2.2), as the search receives it: a contractor narrows
// a box without removing any solution of the problem, or proves that the box holds none
// and says which test did.
#pragma once

#include <cstdint>

#include "numerics/interval.h"

namespace aspects {

struct Refutation {
  enum Kind : uint8_t { None, Equation, HansenSengupta } kind = None;
  int equation = -1;  // Kind::Equation: this equation's projection emptied the box
  explicit operator bool() const { return kind != None; }
};

class Contractor {
 public:
  virtual ~Contractor() = default;
  // Narrows `box`; on a refutation the box holds no solution (its contents are then
  // unspecified).
  virtual Refutation contract(Box& box) = 0;
};

}  // namespace aspects
