// A planning query: where from, where to, what is in the way, where to sample, how big the robot
// is.
#pragma once

#include <memory>
#include <vector>

#include "roomba_rrt/geometry/clearance_map.h"
#include "roomba_rrt/planning/geometry.h"

namespace roomba_rrt::planning {

class GridRegionsCache;

struct Problem {
  Point2 start;
  Point2 goal;
  std::vector<Circle> obstacles;
  Bounds bounds;
  std::vector<Rectangle> rectangles;  ///< axis-aligned obstacles (furniture)
  double robot_radius = 0;            ///< the robot's disc (m); 0 = a point (the lab)
  double clearance = 0;               ///< extra margin kept from obstacles and walls (m)
  /// An occupancy map whose occupied (and, unless it was built to allow them, unknown) cells are
  /// obstacles too, each cell's square exactly; nullptr: none. Built once per map and shared by
  /// every problem planned in it (mapProblem()).
  std::shared_ptr<const geometry::ClearanceMap> map;
  /// The map's regions for region_astar (grid_regions.h), built on first use per radius and
  /// shared by every problem planned in the map; set by mapProblem(). nullptr, or one of another
  /// map: region_astar builds the regions for that one plan.
  std::shared_ptr<const GridRegionsCache> regions;
};

/// How far the robot's centre must stay from obstacles and walls: robot_radius + clearance.
inline double robotMargin(const Problem& problem) {
  return problem.robot_radius + problem.clearance;
}

/// A map as a planning problem (scenario `map`): bounds = its extent, obstacles = its occupied
/// cells, and its unknown cells unless `allow_unknown`. Start, goal and the robot are the
/// caller's. Costs the map's distance transform (about 10 ns per cell).
Problem mapProblem(std::shared_ptr<const geometry::OccupancyGrid> map, bool allow_unknown = false);

}  // namespace roomba_rrt::planning
