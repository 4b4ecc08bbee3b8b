// The map of its home a robot is given before it starts, which may be stale (issue 43): the
// apartment as it was mapped, without the furniture that came since. ROS-free.
//
// What the robot makes of it (BuiltMap, built_map.h):
//   - its occupied cells are walls, for good: the robot trusts them and never plans through one,
//     whatever its scans say (a wall the map has stays a wall; give a map without it to clean
//     behind it). Its unknown cells are unknown, as if the robot had not seen them;
//   - its free cells are floor until the robot's own scans or bumper say otherwise: a cell a
//     return ended in, or one more often hit than passed, is occupied from then on (the
//     furniture the map lacks).
// A map_server map (YAML + PGM/PNG) is read as map_server reads it; a world file's room and
// furniture are drawn on kKnownMapResolution cells (a cell any wall or furniture meets is
// occupied), so that both give a grid in the world's frame.
#pragma once

#include <memory>
#include <string>

#include "roomba_rrt/geometry/occupancy_grid.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::exploration {

/// A map of the home, in the world's frame, and the file it came from (for messages).
struct KnownMap {
  std::shared_ptr<const geometry::OccupancyGrid> grid;
  std::string file;
  bool map_file = true;  ///< a map_server YAML (false: a world file, drawn)
};

/// m: the cells a world file's room and furniture are drawn on (the mapper's, gmapping's default).
inline constexpr double kKnownMapResolution = 0.05;

/// Reads `file`: a map_server YAML (geometry::loadMap), or a world file (world::readWorldFile,
/// validated: its room, furniture and `map:` drawn on kKnownMapResolution cells, or its map's
/// when it has one, with a cell of wall round the room). Throws util::InvalidInput naming the
/// file and the field (a missing file, a NaN, a rotated origin, ...).
KnownMap loadKnownMap(const std::string& file);

/// Throws util::InvalidInput naming the map's file and the field when `map` cannot be this
/// robot's home: `resolution` coarser than half the robot's radius (a doorway it passes would
/// not show), a map too large for the mapper (more than 4e7 cells of 0.05 m: `image`), or the
/// robot's initial pose off the map or not on its free floor (`origin`, `room` for a world
/// file: a map of another home, or drawn in another frame). Returns the map's grid.
std::shared_ptr<const geometry::OccupancyGrid> checkKnownMap(const KnownMap& map,
                                                             const world::RobotSpec& robot);

}  // namespace roomba_rrt::exploration
