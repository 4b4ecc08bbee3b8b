// The reachable floor: the floor points within the robot's radius of a centre it can take, the
// measure coverage is reported against. ROS-free.
//
// A lattice point's disc stands for the centres near it, except at the edge of the free space:
// between the last free lattice point and the wall there are centres no lattice point is, and
// their discs reach into corners and the notches of a map's stepped walls. Those are tested
// exactly (world::penetrates), so the reachable floor is what a brute force over centres a tenth
// of a lattice step apart counts (coverage_planner_test holds it to one).
#pragma once

#include "roomba_rrt/coverage/free_space.h"

namespace roomba_rrt::coverage {

/// The floor within the robot's radius r of a centre it can take in `region`'s part of the free
/// space: the region itself, a disc around each of its boundary points (any floor point near the
/// region is nearest to its boundary), and each floor point beyond those discs that a free centre
/// reaches (world::penetrates, exact) in the free space between the region's edge and its blocked
/// neighbours. That space reaches into a corner or a map's stepped wall where no lattice point's
/// disc does. The centres are tried on the circle of radius r around the point (any free centre
/// nearer to it lies in free space that extends beyond the circle, so crosses it), in
/// kReachDirections directions, first towards the region. (A disc of r + h/2 around the
/// boundary points would also count floor no centre reaches, in a map's stepped walls.)
Mask floorReachedFrom(const FreeSpace& space, const Mask& region);

/// Directions floorReachedFrom() tries around a floor point for a centre that reaches it: 256,
/// centres 4 mm apart on the circle of the robot's radius (128 miss some of the steps of a wall
/// a map draws at 45°).
constexpr int kReachDirections = 256;

/// A centre floorReachedFrom() counts lies within this many lattice steps (each way) of the
/// region: in the free space between the region's edge and the blocked points next to it.
constexpr int kNearRegion = 2;

}  // namespace roomba_rrt::coverage
