#include "roomba_rrt/world/world.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <set>
#include <utility>

#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/util/require.h"

namespace roomba_rrt::world {

namespace {

using util::entry;
using util::InvalidInput;
using util::member;
using util::requirePositive;
using util::show;

[[noreturn]] void fail(const std::string& field, const std::string& problem) {
  throw InvalidInput(field, problem);
}

/// Every named coordinate under `prefix` ("initial_pose" + ".x") is within the supported range.
void requireCoordinates(const std::string& prefix,
                        std::initializer_list<std::pair<const char*, double>> values) {
  for (const auto& [key, value] : values) {
    util::requireInRange(member(prefix, key), value, -WorldLimits::kMaxCoordinate,
                         WorldLimits::kMaxCoordinate);
  }
}

/// A robot's size and speed limits, named under `prefix` ("robot" or "robots[1]").
void requireRobotLimits(const std::string& prefix, const RobotSpec& r) {
  requirePositive(member(prefix, "radius"), r.radius, WorldLimits::kMaxRobotRadius);
  requirePositive(member(prefix, "max_linear_speed"), r.max_linear_speed, WorldLimits::kMaxSpeed);
  requirePositive(member(prefix, "max_angular_speed"), r.max_angular_speed, WorldLimits::kMaxSpeed);
}

/// A ROS graph name without slashes, so that it can be a namespace and a tf prefix.
bool isRobotName(const std::string& name) {
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) return false;
  for (const char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  }
  return true;
}

/// The named robots: names, sizes, speeds, poses inside the free floor, no two discs overlapping.
void validateRobots(const World& world) {
  const std::vector<RobotSpec>& robots = world.robots;
  if (robots.size() > kMaxRobots) {
    fail("robots", "has " + std::to_string(robots.size()) + " entries; at most " +
                       std::to_string(kMaxRobots) + " are supported");
  }
  std::set<std::string> names;
  for (std::size_t i = 0; i < robots.size(); ++i) {
    const RobotSpec& r = robots[i];
    const std::string prefix = entry("robots", i);
    if (!isRobotName(r.name)) {
      fail(member(prefix, "name"),
           "must start with a letter and hold only letters, digits and '_', got '" + r.name + "'");
    }
    if (!names.insert(r.name).second) fail(member(prefix, "name"), "repeats '" + r.name + "'");
    requireRobotLimits(prefix, r);
    sensors::validate(r.sensors, member(prefix, "sensors"), r.radius, world.step);
    if (r.max_linear_speed * world.step >= r.radius) {
      fail("step", "is too long: " + r.name + " would move more than its radius in one step");
    }
    const robot::Pose2D& p = r.initial_pose;
    requireCoordinates(member(prefix, "initial_pose"),
                       {{"x", p.x}, {"y", p.y}, {"theta", p.theta}});
    if (penetrates(world, r.radius, p.x, p.y)) {
      fail(member(prefix, "initial_pose"), "(" + show(p.x) + ", " + show(p.y) + ") puts " + r.name +
                                               "'s disc inside a wall or a piece of furniture");
    }
    for (std::size_t j = 0; j < i; ++j) {
      const RobotSpec& o = robots[j];
      const double reach = r.radius + o.radius;
      if (std::hypot(p.x - o.initial_pose.x, p.y - o.initial_pose.y) < reach) {
        fail(member(prefix, "initial_pose"), "puts " + r.name + " on top of " + o.name);
      }
    }
  }
}

/// The cells of a coverage grid of `cell_size` over the world's room.
double coverageCells(const World& world, double cell_size) {
  return std::ceil(world.room.width / cell_size) * std::ceil(world.room.height / cell_size);
}

std::size_t furnitureCount(const World& world) {
  return world.room.circles.size() + world.room.rectangles.size();
}

/// room.width and room.height.
void requireRoomSize(const Room& room) {
  requirePositive("room.width", room.width, WorldLimits::kMaxRoomSize);
  requirePositive("room.height", room.height, WorldLimits::kMaxRoomSize);
}

/// The furniture's count, the coverage grid's size, and a room wider and higher than a disc of
/// `robot_radius`.
void requireRoomFits(const World& world, double robot_radius) {
  using L = WorldLimits;
  const std::size_t furniture = furnitureCount(world);
  if (furniture > L::kMaxFurniture) {
    fail("furniture", "has " + std::to_string(furniture) + " pieces; at most " +
                          std::to_string(L::kMaxFurniture) + " are supported");
  }
  if (!coverageGridFits(world, world.coverage_cell_size)) {
    const double cells = coverageCells(world, world.coverage_cell_size);
    fail("coverage_cell_size",
         "(" + show(world.coverage_cell_size) + ") is too small for a " + show(world.room.width) +
             " x " + show(world.room.height) + " m room with " + std::to_string(furniture) +
             " pieces of furniture: " + show(cells) + " cells, at most " +
             show(std::min(L::kMaxCoverageCells, L::kMaxGridWork / (1.0 + furniture))) +
             " are supported");
  }
  for (const auto& [name, size] :
       {std::pair{"room.width", world.room.width}, {"room.height", world.room.height}}) {
    const double diameter = 2 * robot_radius;
    if (size <= diameter) {
      fail(name, "(" + show(size) + ") must exceed the robot's diameter " + show(diameter));
    }
  }
}

/// Each piece of furniture: finite coordinates, a positive size.
void requireFurniture(const Room& room) {
  for (std::size_t i = 0; i < room.circles.size(); ++i) {
    const Circle& c = room.circles[i];
    const std::string name = entry("furniture.circles", i);
    requireCoordinates(name, {{"x", c.center.x}, {"y", c.center.y}});
    requirePositive(member(name, "radius"), c.radius, WorldLimits::kMaxRoomSize);
  }
  for (std::size_t i = 0; i < room.rectangles.size(); ++i) {
    const Rectangle& b = room.rectangles[i];
    const std::string name = entry("furniture.rectangles", i);
    requireCoordinates(
        name, {{"min_x", b.min_x}, {"min_y", b.min_y}, {"max_x", b.max_x}, {"max_y", b.max_y}});
    if (!(b.max_x > b.min_x)) fail(member(name, "max_x"), "must be greater than min_x");
    if (!(b.max_y > b.min_y)) fail(member(name, "max_y"), "must be greater than min_y");
  }
}

/// The rays of one scan of every robot's sensors together, within SensorLimits.
void requireSensorRays(const World& world) {
  std::size_t rays = 0;
  for (const RobotSpec& r : world.robots) {
    for (const sensors::RangeSensorSpec& s : r.sensors) rays += std::max(s.samples, 0);
  }
  if (rays > sensors::SensorLimits::kMaxWorldSamples) {
    fail(world.namedRobots() ? "robots" : "sensors",
         "have " + std::to_string(rays) + " samples per scan over all robots; at most " +
             std::to_string(sensors::SensorLimits::kMaxWorldSamples) + " are supported");
  }
}

}  // namespace

double largestRadius(const World& world) {
  double radius = 0;
  for (const RobotSpec& r : world.robots) radius = std::max(radius, r.radius);
  return radius;
}

bool coverageGridFits(const World& world, double cell_size) {
  // The coverage grid holds two bits per cell and tests every cell against every piece of
  // furniture once at start: both must stay small.
  const double cells = coverageCells(world, cell_size);
  return cells <= WorldLimits::kMaxCoverageCells &&
         cells * (1.0 + static_cast<double>(furnitureCount(world))) <= WorldLimits::kMaxGridWork;
}

double defaultCoverageCellSize(const World& world) {
  double cell = World{}.coverage_cell_size;
  // At most 0.8 m (validate() accepts up to 1 m): a world that does not fit even then (a
  // kilometre of room full of furniture, a size that is not finite) keeps it, for validate() to
  // refuse with the numbers.
  while (2 * cell <= 1.0 && !coverageGridFits(world, cell)) cell *= 2;
  return cell;
}

void validate(const World& world, PoseSource pose) {
  using L = WorldLimits;
  if (world.robots.empty()) fail("robots", "must hold at least one robot");
  const bool named = world.namedRobots();
  requireRoomSize(world.room);
  if (!named) requireRobotLimits("robot", world.robot());
  util::requireInRange("step", world.step, L::kMinStep, L::kMaxStep);
  if (!named) sensors::validate(world.robot().sensors, "sensors", world.robot().radius, world.step);
  requireSensorRays(world);
  util::requireInRange("coverage_cell_size", world.coverage_cell_size, L::kMinCellSize, 1.0);
  requireRoomFits(world, largestRadius(world));
  const RobotSpec& robot = world.robot();
  if (!named && robot.max_linear_speed * world.step >= robot.radius) {
    fail("step", "is too long: the robot would move more than its radius in one step");
  }
  requireFurniture(world.room);
  if (named) {
    validateRobots(world);
    return;
  }
  const robot::Pose2D& p = robot.initial_pose;
  requireCoordinates("initial_pose", {{"x", p.x}, {"y", p.y}, {"theta", p.theta}});  // |v| ≤ 1e4
  if (pose == PoseSource::kWorldFile && penetrates(world, p.x, p.y)) {
    fail("initial_pose",
         "(" + show(p.x) + ", " + show(p.y) +
             ") puts the robot's disc inside a wall or a piece of " +
             (world.room.map ? "furniture, or on a blocked cell of the map: give the robot a free "
                               "initial_pose (x, y)"
                             : "furniture"));
  }
}

void validateRoom(const World& world, double robot_radius) {
  requireRoomSize(world.room);
  util::requireInRange("coverage_cell_size", world.coverage_cell_size, WorldLimits::kMinCellSize,
                       1.0);
  requireRoomFits(world, robot_radius);
  requireFurniture(world.room);
}

void useMap(World& world, std::shared_ptr<const geometry::OccupancyGrid> grid,
            const std::string& map_file) {
  // The room is the map's known part (OccupancyGrid::knownExtent()), its edges walls.
  const geometry::Rectangle known = grid->knownExtent();
  world.room.origin = {known.min_x, known.min_y};
  world.room.width = known.max_x - known.min_x;
  world.room.height = known.max_y - known.min_y;
  world.robot().initial_pose = {0.0, 0.0, 0.0};
  world.room.map_file = map_file;
  world.room.map = std::move(grid);
}

World mapWorld(std::shared_ptr<const geometry::OccupancyGrid> grid, double robot_radius) {
  World world;
  useMap(world, std::move(grid), "");
  world.robot().radius = robot_radius;
  world.coverage_cell_size = defaultCoverageCellSize(world);
  return world;
}

World cropped(World world, const geometry::Rectangle& region, const std::string& field) {
  // A map's whole extent may be named (its unknown border too); what is kept is the room's part.
  const geometry::Rectangle room{world.room.origin.x, world.room.origin.y,
                                 world.room.origin.x + world.room.width,
                                 world.room.origin.y + world.room.height};
  const geometry::Rectangle world_box = world.room.map ? world.room.map->extent() : room;
  const geometry::Rectangle& r = region;
  const auto refuse = [&] {
    return InvalidInput(
        field, "must lie within the world (" + util::show(world_box.min_x) + ", " +
                   util::show(world_box.min_y) + ") to (" + util::show(world_box.max_x) + ", " +
                   util::show(world_box.max_y) + ") and keep a part of its room (" +
                   util::show(room.min_x) + ", " + util::show(room.min_y) + ") to (" +
                   util::show(room.max_x) + ", " + util::show(room.max_y) +
                   ") wider and higher than the robot, got (" + util::show(r.min_x) + ", " +
                   util::show(r.min_y) + ") to (" + util::show(r.max_x) + ", " +
                   util::show(r.max_y) + ")");
  };
  if (!(r.min_x >= world_box.min_x && r.min_y >= world_box.min_y && r.max_x <= world_box.max_x &&
        r.max_y <= world_box.max_y)) {
    throw refuse();
  }
  // Whole cells, inside the region (the robot cleans nothing it was not asked to): the lower-left
  // corner moves in to the map's grid, then the width and height shrink to whole coverage cells,
  // unless the region reaches the room's own wall. The coverage lattice starts at the corner, so
  // the walls the cut makes lie on its cells' boundaries, as the map's own walls do when its cell
  // is a multiple of the coverage cell. A wall between two lattice points leaves floor within
  // the rows' clearance of it, which they never sweep: 84 of 120 random crops reached 99 % by
  // twice the ideal time cut anywhere, 96 cut to whole cells (bench/coverage_crops.py).
  constexpr double kSlack = 1e-6;  // in cells: 4.2 m is 140 cells of 3 cm, not 139.99…
  geometry::Point2 corner{std::max(r.min_x, room.min_x), std::max(r.min_y, room.min_y)};
  if (world.room.map) {
    const geometry::OccupancyGrid& grid = *world.room.map;
    const auto onGrid = [&](double v, double grid_origin) {
      return grid_origin +
             std::ceil((v - grid_origin) / grid.resolution - kSlack) * grid.resolution;
    };
    corner = {onGrid(corner.x, grid.origin.x), onGrid(corner.y, grid.origin.y)};
  }
  const geometry::Point2 far{std::min(r.max_x, room.max_x), std::min(r.max_y, room.max_y)};
  world.room.origin = corner;
  world.room.width = far.x - corner.x;
  world.room.height = far.y - corner.y;
  if (!world.coverage_cell_size_given) {  // the region's own: a crop of a large map is finer
    world.coverage_cell_size = defaultCoverageCellSize(world);
  }
  const double cell = world.coverage_cell_size;
  const auto wholeCells = [&](double size, bool to_wall) {
    return to_wall ? size : std::floor(size / cell + kSlack) * cell;
  };
  world.room.width = wholeCells(world.room.width, far.x >= room.max_x);
  world.room.height = wholeCells(world.room.height, far.y >= room.max_y);
  // Whole cells only shrink the part kept: one test covers the region as asked and as kept.
  const double diameter = 2 * world.robot().radius;
  if (!(world.room.width > diameter && world.room.height > diameter)) {
    throw refuse();
  }
  return world;
}

}  // namespace roomba_rrt::world
