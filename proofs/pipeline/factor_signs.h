// The sign of each determinant factor d1..dp on an output box (paper 4.4.2): +1 or −1
// only when the factor's enclosure clears 0 by the margin of checker_margins.h, so that
// another sound enclosure (check_cert's) confirms it; 0 when it may vanish on the box.
#pragma once

#include <cstdint>
#include <vector>

#include "model/determinant_factors.h"
#include "model/model.h"
#include "model/model_eval.h"

namespace aspects {

class FactorSigns {
 public:
  FactorSigns(ModelEvaluator& ev, const Model& m, const std::vector<Factor>& factors);
  int factors() const { return int(nodes_.size()); }
  // Writes factors() signs on the box as stored: its ends rounded outward to doubles.
  void of(const Box& box, int8_t* signs);

 private:
  ModelEvaluator& ev_;
  std::vector<int> nodes_, program_;
  Box stored_;
};

}  // namespace aspects
