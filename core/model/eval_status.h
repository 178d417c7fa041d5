// What an interval evaluation of a program says about the points of the box.
#pragma once

namespace aspects {

enum class EvalStatus {
  Defined,    // every node of the program is defined on the whole box
  Partial,    // some node is undefined somewhere in the box (e.g. sqrt of [-1, 4], or
              // the derivative of abs/min/max where a kink may lie in the box)
  Undefined,  // some node is defined nowhere in the box: no point of the box is feasible
};

}  // namespace aspects
