// Poses given on the command line, and whether a pose lies in a box's pose part.
// A periodic pose coordinate stands for its values modulo 2π: the model is 2π-periodic
// in it, so the command of p + 2πk is the command of p.
#pragma once

#include <string>
#include <vector>

#include "model/model.h"

namespace aspects {

// Parses "X1,X2[,X3]" (decimal numbers, pose order). Throws UsageError naming `option`
// when a number is malformed, the count differs from the model's pose count, or a
// non-periodic coordinate lies outside its declared domain.
std::vector<double> parse_pose(const std::string& text, const std::string& option,
                               const Model& model);

// Certainly p + 2πk ∈ [lo, hi] for some integer k (k = 0 when not periodic), with the
// sum computed in MPFI: a pose on the boundary of a box lies in it (boxes are closed).
bool coordinate_in(double p, double lo, double hi, bool periodic);

// The pose (pose order) lies in the pose part of a box given in model order.
bool pose_in_box(const Model& m, const std::vector<double>& pose, const double* lo,
                 const double* hi);

// Distance between poses, each periodic coordinate taken modulo 2π (shortest way round).
double pose_distance(const std::vector<double>& a, const std::vector<double>& b,
                     const std::vector<bool>& periodic);

std::string format_pose(const std::vector<double>& pose);

}  // namespace aspects
