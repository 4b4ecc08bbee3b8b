// The exact Euclidean distance transform of an occupancy grid: for every cell, how far its centre
// is from the nearest blocked cell's centre. The planner inflates a map with it (see
// clearance_map.h).
#pragma once

#include <cstdint>
#include <vector>

#include "roomba_rrt/geometry/occupancy_grid.h"

namespace roomba_rrt::geometry {

/// No blocked cell in the grid at all: the value of every cell.
constexpr std::int32_t kNoBlockedCell = INT32_MAX;

/// For every cell (i, j), in the grid's order (cells[j · width + i]), the squared distance in
/// cells² from its centre to the nearest blocked cell's centre (0 on a blocked cell): the exact
/// Euclidean distance transform, min over blocked (k, l) of (i − k)² + (j − l)², an integer.
/// Blocked is OccupancyGrid::blocked() inside the grid; cells outside the grid do not count here
/// (their walls are the map's edges, which callers check as a rectangle). Values above
/// kNoBlockedCell − 1 are clamped to it.
///
/// Felzenszwalb and Huttenlocher's two passes (Theory of Computing 8, 2012): along each column
/// the distance to the nearest blocked cell by two sweeps, then along each row the lower envelope
/// of the parabolas (i − k)² + g(k)². Both passes run over rows, in memory order. Cost: O(cells).
std::vector<std::int32_t> squaredDistanceTransform(const OccupancyGrid& grid,
                                                   bool unknown_is_free = false);

}  // namespace roomba_rrt::geometry
