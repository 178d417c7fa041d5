// A straight segment of the unwrapped pose space certified through a chain of linked
// solution boxes of one CSNC (paper 4.1, 4.3).
//
// Certification argument. The segment P(t) = P + t(Q − P), t ∈ [0, 1], is cut at crossing
// points P(t_1) ≤ ... ≤ P(t_m) (t increasing) into pieces; piece i lies in the pose part of
// box B_i placed at B_i's shift (a box is convex: both ends in it suffice). On a box, P1 and
// P2 make κ_B the unique, continuous, nonsingular command (path_plan.h). At a crossing,
// B_i and B_i+1 are linked (P3, proved again) with the pose shift of their placements, so
// κ agrees at the link's witness x̂ ∈ D = [x_i] ∩ ([x_i+1] + 2πk); the points of D where the
// two agree form a closed set (both continuous) and an open one (at such a point (x, q),
// Fq is nonsingular, so the implicit function theorem gives one solution branch near q,
// which both follow), and D, a box, is connected: they agree on all of D, in particular at
// the crossing, which lies in both. So the pieces join into one continuous nonsingular
// motion along the segment. A crossing is the point where a chosen pose coordinate equals
// a chosen number (a double plus whole turns): t is then an exact real, enclosed with
// interval arithmetic to check the other coordinates and the order of the crossings.
#pragma once

#include <string>
#include <vector>

#include "csnc_links.h"

namespace aspects {

// The point of the segment where pose coordinate `coordinate` equals value + 2π·turns.
struct Crossing {
  int coordinate = 0;
  double value = 0;
  long turns = 0;
};

// A point of the unwrapped pose space: pose + 2π·turns (pose order).
struct UnwrappedPose {
  std::vector<double> pose;
  std::vector<long> turns;
};

struct Segment {
  std::vector<PlacedBox> boxes;      // in order along the segment, at least one
  std::vector<Crossing> crossings;   // boxes.size() − 1: from boxes[i] into boxes[i + 1]
};

enum class SegmentCheck {
  Certified,
  NotInCsnc,        // a box of another CSNC
  EndOutside,       // an end of the segment is not (decidedly) in its box
  CrossingOutside,  // a crossing is not proved to lie in both its boxes
  CrossingsUnordered,  // the crossings are not proved to come in order along the segment
  NotLinked,        // two consecutive boxes whose link could not be proved
  Malformed,        // counts do not match
};

const char* segment_check_name(SegmentCheck c);

// Checks a segment from `from` to `to` as the argument above needs it.
SegmentCheck check_segment(const LoadedResult& r, CsncLinks& links, const UnwrappedPose& from,
                           const UnwrappedPose& to, const Segment& s);

// Whether the unwrapped pose lies in the box's pose part placed at its shift (exact).
bool in_placed_box(const LoadedResult& r, const UnwrappedPose& x, const PlacedBox& b);

// A chain of linked boxes of the CSNC that carries the segment, starting in `start`
// (which must hold `from`); proves the links it uses. False when none was found (a
// heuristic walk: the segment may leave the CSNC, or cross where no link is proved).
bool find_segment(const LoadedResult& r, CsncLinks& links, const UnwrappedPose& from,
                  const UnwrappedPose& to, const PlacedBox& start, Segment& s);

}  // namespace aspects
