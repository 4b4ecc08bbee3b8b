// Maps between the ROS-free occupancy grid and nav_msgs: what roomba_sim publishes on /map (as
// map_server would) and what rrt_planner reads from it (from any map_server, SLAM node or bag).
#pragma once

#include <string>

#include <nav_msgs/MapMetaData.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/time.h>

#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/geometry/occupancy_grid.h"

namespace roomba_rrt::nodes {

/// The grid as map_server publishes it on /map (latched, frame "map"): the same cells, resolution
/// and origin as the map file, and its /map_metadata.
nav_msgs::OccupancyGrid toMapMessage(const geometry::OccupancyGrid& grid, const ros::Time& stamp);
nav_msgs::MapMetaData toMapMetaData(const geometry::OccupancyGrid& grid, const ros::Time& stamp);

/// The largest map a node takes from a topic (cells): map_file.h's limit for files.
constexpr long long kMaxMapMessageCells = geometry::MapLimits::kMaxCells;

/// A received map as a grid: cells as they come (0 free, −1 unknown, anything else occupied, as
/// a costmap's probabilities are). Returns "" or why the message cannot be a map, naming its
/// field, by the checks a map file gets (geometry::validateMapPlacement: resolution, origin, no
/// rotation, roll and pitch included) and its size: "info.resolution: must be in [0.0001, 100]
/// m, got 1e-30", "data: 10 cells for 4 x 3", "info.origin.orientation: a rotated map (by 0.3
/// rad) is not supported; ...". `grid` is written only when the message is a map.
std::string fromMapMessage(const nav_msgs::OccupancyGrid& message, geometry::OccupancyGrid* grid);

}  // namespace roomba_rrt::nodes
