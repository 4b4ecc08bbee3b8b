#include "roomba_rrt/exploration/known_map.h"

#include <cmath>
#include <utility>

#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/mapping/map_accuracy.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::exploration {
namespace {

/// The most cells of 0.05 m a known map may cover (the mapper's max_cells).
constexpr double kMaxMapperCells = 4e7;

/// `world`'s room and furniture (and map) drawn on cells of `resolution`, with one cell of wall
/// round the room: a cell whose square any of them meets is occupied (mapping::cellTruth).
geometry::OccupancyGrid drawWorld(const world::World& world, double resolution) {
  const world::Room& room = world.room;
  geometry::OccupancyGrid grid;
  grid.resolution = resolution;
  grid.origin = {room.origin.x - resolution, room.origin.y - resolution};
  grid.width = static_cast<int>(std::ceil(room.width / resolution - 1e-9)) + 2;
  grid.height = static_cast<int>(std::ceil(room.height / resolution - 1e-9)) + 2;
  grid.cells.assign(static_cast<std::size_t>(grid.width) * grid.height,
                    geometry::OccupancyGrid::kFree);
  for (int j = 0; j < grid.height; ++j) {
    for (int i = 0; i < grid.width; ++i) {
      if (mapping::cellTruth(world, grid.square(i, j)) != mapping::CellTruth::kFree) {
        grid.cells[static_cast<std::size_t>(j) * grid.width + i] =
            geometry::OccupancyGrid::kOccupied;
      }
    }
  }
  return grid;
}

}  // namespace

KnownMap loadKnownMap(const std::string& file) {
  KnownMap known;
  known.file = file;
  if (geometry::isMapYaml(file)) {
    known.grid = std::make_shared<const geometry::OccupancyGrid>(geometry::loadMap(file).grid);
    return known;
  }
  known.map_file = false;
  world::World world = world::readWorldFile(file).world;
  try {
    world::validate(world, world::PoseSource::kElsewhere);  // a NaN, a room of no size, ...
  } catch (const util::InvalidInput& e) {
    throw e.in(file);
  }
  const bool map_only =
      world.room.map && world.room.circles.empty() && world.room.rectangles.empty();
  known.grid = std::make_shared<const geometry::OccupancyGrid>(
      map_only
          ? *world.room.map
          : drawWorld(world, world.room.map ? world.room.map->resolution : kKnownMapResolution));
  return known;
}

std::shared_ptr<const geometry::OccupancyGrid> checkKnownMap(const KnownMap& map,
                                                             const world::RobotSpec& robot) {
  const geometry::OccupancyGrid& grid = *map.grid;
  if (!(grid.resolution <= robot.radius / 2)) {
    throw util::InvalidInput(
        "resolution",
        "must be at most half the robot's radius (" + util::show(robot.radius / 2) +
            " m: a doorway it passes shows), got " + util::show(grid.resolution),
        map.file);
  }
  const geometry::Rectangle extent = grid.extent();
  const double cells = std::ceil((extent.max_x - extent.min_x) / kKnownMapResolution) *
                       std::ceil((extent.max_y - extent.min_y) / kKnownMapResolution);
  if (!(cells <= kMaxMapperCells)) {
    throw util::InvalidInput("image",
                             "covers " + util::show(extent.max_x - extent.min_x) + " m x " +
                                 util::show(extent.max_y - extent.min_y) +
                                 " m: more than the 4e7 cells of 0.05 m the robot maps",
                             map.file);
  }
  const robot::Pose2D& start = robot.initial_pose;
  const int i = grid.column(start.x), j = grid.row(start.y);
  const std::string field = map.map_file ? "origin" : "room";
  const std::string at =
      "the robot's start (" + util::show(start.x) + ", " + util::show(start.y) + ")";
  if (!grid.inside(i, j)) {
    throw util::InvalidInput(field,
                             at + " is off the map, which covers (" + util::show(extent.min_x) +
                                 ", " + util::show(extent.min_y) + ") to (" +
                                 util::show(extent.max_x) + ", " + util::show(extent.max_y) +
                                 "): a map of another home, or in another frame",
                             map.file);
  }
  if (grid.at(i, j) != geometry::OccupancyGrid::kFree) {
    throw util::InvalidInput(
        field,
        at + " is on " +
            (grid.at(i, j) == geometry::OccupancyGrid::kUnknown ? "an unknown" : "an occupied") +
            " cell of the map, not its floor: a map of another home, or in "
            "another frame",
        map.file);
  }
  return map.grid;
}

}  // namespace roomba_rrt::exploration
