// A certified point of W_s in a box: a point of the solution set V in the box where every
// factor has its sign s_i strictly. Chosen in doubles (a grid of the box's u-part, Newton
// for w), then proved: iteration (9) at the u-point gives a unique w in an enclosure that
// lies in the box's w-part, and on (u, enclosure) each factor's enclosure has sign s_i.
// A piece's star centre is one (its piece is nonempty); a point in the inner intersection of
// two boxes joins their pieces of class s (an adjacency "joined").
#pragma once

#include <cstdint>
#include <vector>

#include "counting/chart.h"
#include "counting/factor_gradients.h"
#include "model/constraints.h"

namespace aspects {

struct ClassPoint {
  std::vector<int> u_vars, w_vars;  // the chart's variables
  std::vector<double> u;            // the u-point, n doubles (u_vars order)
  std::vector<Interval> w;          // the enclosure of its unique w (w_vars order)
};

enum class PointVerdict : uint8_t { Found, NotFound };

// With constraints, a point must satisfy every one, certainly: `check` must find them all
// True on (u, the enclosure of w) (model/constraints.h). `atoms` (the atoms' gradients'
// values, indices `which`) are the atoms left Unknown on the box: a choice of the sample
// deepest in them too.
struct PointConstraints {
  ConstraintChecker* check = nullptr;
  const FactorGradients* atoms = nullptr;
  std::vector<int> which;
};

// The search for the points of every class in one box and chart: the grid's u-points and
// their w (Newton in doubles) do not depend on the class, so they are computed once and
// each class is then a choice among them (then a climb, then the proof).
class ClassPointSearch {
 public:
  // w_vars: the chart's w (the unknowns). per_axis: grid points per u-axis.
  ClassPointSearch(ModelEvaluator& ev, const FactorGradients& fg, const Box& box,
                   const std::vector<int>& w_vars, int per_axis,
                   const PointConstraints* constraints = nullptr);
  // cls: bit i set when factor i is positive.
  PointVerdict find(uint32_t cls, HsWorkspace& ws, ClassPoint& out);

 private:
  struct Sample {
    std::vector<double> u, w;
    std::vector<double> g;  // the factors at (u, w), each over its scale on the box
    double face = 0;        // the least distance to a face of W, over W's width, and to the
                            // zero of an atom left Unknown, over its scale
  };
  bool sample(std::vector<double> u, const std::vector<double>* start, Sample& out);
  double margin(const Sample& s, uint32_t cls) const;
  bool prove(const Sample& s, uint32_t cls, HsWorkspace& ws, ClassPoint& out);

  ModelEvaluator& ev_;
  const FactorGradients& fg_;
  const Box& box_;
  std::vector<int> u_vars_, w_vars_;
  int per_axis_;
  const PointConstraints* pc_;
  std::vector<double> scale_;  // per factor: its magnitude over the box (1 if unknown)
  std::vector<double> atom_scale_;  // per atom of pc_->which, likewise
  std::vector<Sample> grid_;
  Box pt_;
  std::vector<Interval> values_;
};

// One class: ClassPointSearch(...).find(cls, ...).
PointVerdict find_class_point(ModelEvaluator& ev, const FactorGradients& fg, const Box& box,
                              const std::vector<int>& w_vars, uint32_t cls, HsWorkspace& ws,
                              ClassPoint& out, int per_axis = 5,
                              const PointConstraints* constraints = nullptr);

}  // namespace aspects
