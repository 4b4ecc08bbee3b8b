// A goal that is not free, relaxed as move_base relaxes it: the nearest free point within a
// tolerance (nav_msgs/GetPlan's `tolerance`).
#pragma once

#include <optional>

#include "roomba_rrt/planning/problem.h"

namespace roomba_rrt::planning {

/// `p` itself when the robot's disc is free there (inside the bounds shrunk by robot_radius +
/// clearance and clear of every obstacle and map cell); otherwise the free point nearest to p
/// among the points of a lattice within `tolerance` of p in x and in y (navfn's square), spaced by
/// the map's resolution (tolerance / 20 without a map; at most 401 × 401 points); std::nullopt when
/// none is free. A tolerance ≤ 0 or not finite only tries p.
std::optional<Point2> freePointNear(const Problem& problem, const Point2& p, double tolerance);

}  // namespace roomba_rrt::planning
