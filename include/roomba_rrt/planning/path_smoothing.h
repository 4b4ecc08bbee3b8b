// Shortcut smoothing of a path.
#pragma once

#include <cstdint>
#include <vector>

#include "roomba_rrt/planning/collision_checker.h"
#include "roomba_rrt/planning/geometry.h"

namespace roomba_rrt::planning {

/// `tries` times: pick two vertices i < j of the path at random (own MATLAB stream seeded with
/// `seed`, so the result is reproducible) and, when the straight segment between them is free
/// (exact segment test, whatever the planner's mode), drop the vertices in between.
/// The endpoints never move and, by the triangle inequality, the path never gets longer.
std::vector<Point2> shortcutPath(std::vector<Point2> path, const CollisionChecker& checker,
                                 int tries, std::uint32_t seed);

}  // namespace roomba_rrt::planning
