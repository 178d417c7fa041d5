// The shortcut of a path found as a chain (path_plan.h): from each kept waypoint, the
// farthest later waypoint that one straight segment reaches through linked boxes
// (find_segment), certified by check_segment, replaces the waypoints between.
#pragma once

#include "path_plan.h"

namespace aspects {

// Replaces p's waypoints and segments by the shortcut's when every segment is certified
// and every kept waypoint's command proved; else leaves p as it was and returns false.
bool shortcut_path(const LoadedResult& r, ModelEvaluator& ev, CsncLinks& links, PathResult& p);

}  // namespace aspects
