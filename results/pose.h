// Poses given on the command line, and whether a pose lies in a box's pose part.
// A periodic pose coordinate stands for its values modulo 2π: the model is 2π-periodic
// in it, so the command of p + 2πk is the command of p. Membership is decided exactly:
// a negative answer of `query` or `path` rests on it, so a test that is only sure of
// "inside" would turn every pose near a face into a false "in no box".
#pragma once

#include <mpfr.h>

#include <string>
#include <vector>

#include "model/model.h"

namespace aspects {

// Parses "X1,X2[,X3]" (numbers as parse_number reads them, pose order; each pose is the
// double nearest the number, a subnormal included). Throws UsageError naming `option` when a number is malformed, the count
// differs from the model's pose count, a non-periodic coordinate lies outside its declared
// domain, or a periodic one is larger than kMaxPeriodicCoordinate in magnitude.
std::vector<double> parse_pose(const std::string& text, const std::string& option,
                               const Model& model);

// A pose given as numbers (a front end's list), checked as parse_pose checks text: each
// printed with 17 digits, which parse back to the same double. Throws UsageError naming
// `what`; an empty list is refused too.
std::vector<double> checked_pose(const std::vector<double>& pose, const std::string& what,
                                 const Model& model);

// Keeps the number of turns k small (an int).
constexpr double kMaxPeriodicCoordinate = 1e6;

enum class Membership {
  Inside,     // certainly inside (closed box: a point on a face is inside)
  Outside,    // certainly outside
  Undecided,  // max_prec bits did not separate p + 2πk from a face (see below)
};

// The precision at which deciding stops. p + 2πk never equals a double when k ≠ 0
// (π is irrational), so enough bits always decide; a double within 2^-65536 of p + 2πk
// is not known to exist.
constexpr mpfr_prec_t kMaxMembershipPrecision = mpfr_prec_t(1) << 16;

// Sign of p + 2πk − b for k ≠ 0, decided with at most max_prec bits of π; 0: undecided.
int shifted_sign(double p, long k, double b, mpfr_prec_t max_prec = kMaxMembershipPrecision);

// Whether p + 2πk ∈ [lo, hi] for some integer k (k = 0 only when not periodic); when
// Inside, `turns` is such a k.
Membership coordinate_membership(double p, double lo, double hi, bool periodic, long& turns,
                                 mpfr_prec_t max_prec = kMaxMembershipPrecision);

// The pose (pose order) in the pose part of a box given in model order; when Inside,
// `turns` (pose order, if given) holds each coordinate's k.
Membership pose_in_box(const Model& m, const std::vector<double>& pose, const double* lo,
                       const double* hi, std::vector<long>* turns = nullptr);

// The same for a box given by its pose part only (pose order).
Membership pose_in_pose_box(const std::vector<bool>& periodic, const std::vector<double>& pose,
                            const double* lo, const double* hi);

// Distance between poses, each periodic coordinate taken modulo 2π (shortest way round).
double pose_distance(const std::vector<double>& a, const std::vector<double>& b,
                     const std::vector<bool>& periodic);

std::string format_pose(const std::vector<double>& pose);

}  // namespace aspects
