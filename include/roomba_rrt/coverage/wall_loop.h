// The loop along the walls: once round the floor the robot's centre can take, as close to the
// walls as the planning radius allows. ROS-free.
//
// Why: boustrophedon rows run along x. Where a wall lies at a slant to them (a map's walls at
// 30° or 60°: the turtlebot3 arena's hexagon), every row ends against it a little further along
// than the one before, and each U-turn leaves a wedge of floor between the two rows' ends and
// the wall: in that arena, 7 % of the floor after the rows, in 40 wedges and the notches of the
// map's stepped walls. Going back to each wedge is a transit and a stop per wedge; driving once
// round the walls sweeps all of them in one pass (what robot vacuums call edge cleaning).
// Where the walls are parallel or square to the rows (most rooms), the rows' ends already sweep
// along them and the loop would be a drive round the room for little floor: CoveragePlanner
// appends it only where it sweeps enough that the rows do not (kMinWallLoopGain).
//
// How: the boundary of the centre's free region on the lattice, traced (Moore neighbours), kept
// to the longest free segments within kLoopTolerance of it, and each segment moved out towards
// the wall as far as it stays free (the lattice stops up to a step short of the walls).
#pragma once

#include "roomba_rrt/coverage/free_space.h"

namespace roomba_rrt::coverage {

/// The outer boundary of the piece of the kFree lattice that lattice point `seed` belongs to (the
/// floor the robot can drive to from there: FreeSpace::piece) as a closed polyline (its first
/// point repeated at the end), every segment free (FreeSpace::segmentFree, planning radius).
/// Holes in the piece (furniture standing free in the room) are not followed. Empty when `seed`
/// is not kFree or the piece has fewer than three boundary points.
Polyline wallLoop(const FreeSpace& space, int seed);

/// The traced boundary's points lie at most this far from the loop's segments (m), before they
/// are moved out to the walls.
constexpr double kLoopTolerance = 0.01;

/// A loop's segment moves out towards the wall by at most this many lattice steps.
constexpr double kLoopPushOut = 1.5;

}  // namespace roomba_rrt::coverage
