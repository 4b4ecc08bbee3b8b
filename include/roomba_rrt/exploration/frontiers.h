// Frontiers: where the floor the robot has seen meets what it has not, and the nearest place it
// can drive to from which it will see past one. ROS-free. A robot exploring a home it has never
// seen (issue 43) goes to the nearest frontier, looks, and repeats until no frontier it can reach
// is left; this file answers "which one, and where do I stand".
//
// On a map the robot built (mapping/, or any nav_msgs/OccupancyGrid: −1 unknown, 0 free, else
// occupied):
//   - a frontier cell is a free cell with an unknown cell beside it (4-neighbours), as in
//     Yamauchi's frontier-based exploration (1997) and ROS's explore_lite;
//   - a frontier is an 8-connected piece of frontier cells; pieces smaller than
//     FrontierOptions::min_cells are the gaps between a lidar's rays, not floor to explore;
//   - the robot reaches a frontier when its centre is within `view_distance` of one of its cells,
//     measured over free floor (not through a wall), with a straight line of free cells through
//     one of them to an unknown cell beside it (it sees past the frontier, not only its way
//     round a corner or a corner's edge), on a cell where its disc
//     keeps clear of every cell that is not known free (unknown counts as a wall until seen: the
//     robot never plans through what it has not seen);
//   - the nearest frontier is the nearest by the length of such a path over the cells' centres
//     (8-connected, Dijkstra), not by a straight line through walls.
// The path is only the measure of "nearest": the robot gets there with the planner, whose checks
// are exact.
#pragma once

#include <optional>
#include <vector>

#include "roomba_rrt/geometry/clearance_map.h"
#include "roomba_rrt/geometry/geometry.h"
#include "roomba_rrt/geometry/occupancy_grid.h"

namespace roomba_rrt::exploration {

struct FrontierOptions {
  double robot_radius = 0.17;  ///< the robot's disc (m)
  double view_distance = 0.5;  ///< a frontier is reached this close to one of its cells (m)
  int min_cells = 3;           ///< smaller pieces of frontier are ignored
};

/// One frontier: its cells (index j · width + i in the map) and their centroid.
struct Frontier {
  std::vector<int> cells;
  geometry::Point2 centroid;
};

/// Where to go next: a cell's centre the robot can drive to, and the frontier it sees from there.
struct FrontierGoal {
  geometry::Point2 goal;
  double path_length = 0;  ///< from the robot's cell, over the cells' centres (m)
  int frontier = 0;        ///< index into the frontiers given
};

/// The frontiers of `map` with at least `min_cells` cells each, in the order of their first cell
/// (row by row from the bottom).
std::vector<Frontier> findFrontiers(const geometry::OccupancyGrid& map, int min_cells);

/// The nearest frontier the robot at `from` can reach (see the file's comment), or nothing when
/// none is reachable: the exploration is done. `known` is the robot's map inflated with unknown
/// cells as walls (ClearanceMap(grid, /*unknown_is_free=*/false)).
std::optional<FrontierGoal> nearestFrontier(const geometry::ClearanceMap& known,
                                            const geometry::Point2& from,
                                            const std::vector<Frontier>& frontiers,
                                            const FrontierOptions& options);
/// The same with "in view" (the way over free floor, and a straight line of free cells to one
/// of the frontier's cells) judged on `sight`, the map the frontiers were found on (the same
/// cells as known's grid), while the way there is judged on `known`: a robot that plans on a
/// stricter map than it sees.
std::optional<FrontierGoal> nearestFrontier(const geometry::ClearanceMap& known,
                                            const geometry::OccupancyGrid& sight,
                                            const geometry::Point2& from,
                                            const std::vector<Frontier>& frontiers,
                                            const FrontierOptions& options);

}  // namespace roomba_rrt::exploration
