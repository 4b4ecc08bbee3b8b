// A path with a point at least every `spacing` metres, as ROS's grid planners (navfn,
// global_planner) answer one pose per map cell: local planners (base_local_planner, DWA, TEB) cut
// the global plan to their window of a few metres, and a plan whose poses are metres apart leaves
// them nothing to follow.
#pragma once

#include <cstddef>
#include <vector>

#include "roomba_rrt/planning/geometry.h"

namespace roomba_rrt::planning {

/// The most points densify() returns unless asked otherwise: a 5 km path at navfn's 5 cm.
inline constexpr std::size_t kMaxDensePoints = 100'000;

/// The path through the same vertices, every edge cut into ceil(length / spacing) equal pieces
/// (so no two consecutive points are more than `spacing` apart, and every vertex is kept). When
/// that would give more than `max_points` points, the spacing grows until it does not (unless the
/// vertices alone are that many: then the path as it is). Repeated vertices stay repeated.
/// `spacing` must be finite and > 0 (otherwise the path as it is).
std::vector<Point2> densify(const std::vector<Point2>& path, double spacing,
                            std::size_t max_points = kMaxDensePoints);

}  // namespace roomba_rrt::planning
