// The simulated world: a room (walls, furniture as circles and axis-aligned rectangles, or a map)
// and the robots in it, with the simulator's step and coverage cell. world_file.h reads it from
// YAML (config/roomba_world.yaml documents the format).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "roomba_rrt/geometry/geometry.h"
#include "roomba_rrt/geometry/occupancy_grid.h"
#include "roomba_rrt/robot/robot_state.h"
#include "roomba_rrt/sensors/range_sensor.h"

namespace roomba_rrt::world {

/// Furniture: round pieces (a table leg, a bin) and axis-aligned rectangular ones (a sofa, a
/// cupboard), in metres; the shapes of the shared geometry module, which the planner uses too.
using geometry::Circle;
using geometry::Rectangle;

/// At most this many robots under `robots:`.
constexpr std::size_t kMaxRobots = 1000;

/// The room the robots live in: its walls, its furniture and, for a map world, its map. Every
/// node that knows the world shares it (the simulator, the planner, navigation, cleaning).
struct Room {
  double width = 6.4;   ///< walls at x = origin.x and x = origin.x + width
  double height = 4.8;  ///< walls at y = origin.y and y = origin.y + height
  /// The room's lower-left corner: (0, 0) for a room of the world file; when the world is a map,
  /// the corner of its known part (the room's walls are then the edges of what was mapped).
  geometry::Point2 origin;
  /// A map (a map_server YAML: `map:` in the world file, or the world file itself): its
  /// occupied and unknown cells are walls, exactly (the disc against each cell's square), and
  /// its known part (OccupancyGrid::knownExtent: the cells that are free or occupied, without
  /// the unknown border a SLAM map has round them) is the room. Copies of the world share the
  /// grid.
  std::shared_ptr<const geometry::OccupancyGrid> map;
  std::string map_file;  ///< the map's YAML, "" without a map
  std::vector<Circle> circles;
  std::vector<Rectangle> rectangles;
};

/// One robot: its size, speed limits and where it starts. The lab's Roomba by default: 0.17 m,
/// 1.0 m/s and 2.0 rad/s, at the lab room's centre facing +x.
struct RobotSpec {
  /// Its namespace and tf prefix (a letter, then letters, digits or '_'), when the world file
  /// names its robots (`robots:`); "" for the one robot of a world file without `robots:`.
  std::string name;
  robot::Pose2D initial_pose{3.2, 2.4, 0.0};
  double radius = 0.17;            ///< m
  double max_linear_speed = 1.0;   ///< |v| is clamped to this, m/s
  double max_angular_speed = 2.0;  ///< |w| is clamped to this, rad/s
  /// Its range sensors (`sensors:`; none here, the LDS preset for a world file that names none):
  /// they sense, and change nothing the robot does.
  std::vector<sensors::RangeSensorSpec> sensors{};
};

/// Everything the simulator needs to know about the room and the robots, and what the planners
/// and behaviours read of it. Defaults are the lab's simulation: a 6.4 m × 4.8 m empty room, one
/// Roomba, steps of 1/60 s.
struct World {
  Room room;
  /// At least one. One unnamed robot is the lab's simulation; named robots (`robots:`) each
  /// get a namespace.
  std::vector<RobotSpec> robots{RobotSpec{}};
  double step = 1.0 / 60.0;  ///< integration step, s

  /// Edge of a coverage grid cell, m. A world file that does not set it gets
  /// defaultCoverageCellSize(): this, or coarser for a world too large for it.
  double coverage_cell_size = 0.025;
  /// The world file set coverage_cell_size (false: the default chose it, and a tool that keeps
  /// a region of the world chooses again for the region).
  bool coverage_cell_size_given = false;

  /// The sections (room, furniture, robot, initial_pose) the world file did not set at all, in
  /// that order: their keys have the defaults above (see defaultsNotice()).
  std::vector<std::string> defaulted_sections;

  /// The first robot: the only one unless the world names several. A node that drives one robot
  /// (roomba_bt, the planner's room) plans for this one.
  const RobotSpec& robot() const { return robots.front(); }
  RobotSpec& robot() { return robots.front(); }
  /// The robots have names (`robots:` in the world file): each its own namespace.
  bool namedRobots() const { return !robots.front().name.empty(); }
};

/// The supported ranges (validate() refuses anything outside them, naming the parameter). They
/// keep every computation finite and the coverage grid's memory and set-up time small.
struct WorldLimits {
  static constexpr double kMaxRoomSize = 1000;           ///< room.width, room.height ≤ this, m
  static constexpr double kMaxRobotRadius = 10;          ///< m
  static constexpr double kMaxSpeed = 100;               ///< m/s and rad/s
  static constexpr double kMinStep = 1e-4;               ///< s
  static constexpr double kMaxStep = 1;                  ///< s
  static constexpr double kMinCellSize = 1e-3;           ///< coverage_cell_size ≥ this, m
  static constexpr double kMaxCoverageCells = 1e7;       ///< cells in the grid (2.5 MB of bits)
  static constexpr double kMaxGridWork = 5e7;            ///< cells × (1 + furniture) at start
  static constexpr std::size_t kMaxFurniture = 1000;     ///< circles + rectangles
  static constexpr double kMaxCoordinate = 1e4;          ///< |furniture, pose coordinates|, m
  static constexpr std::size_t kMaxFileBytes = 1 << 20;  ///< a world file is at most 1 MiB
};

/// Overlap below this (m) is floating-point rounding of a push-back, not penetration.
constexpr double kPenetrationTolerance = 1e-9;

/// True when a disc of `radius` centred at (x, y) overlaps a wall, a piece of furniture or a
/// blocked map cell by more than kPenetrationTolerance (where a robot may not be: validate() and
/// the simulator's contact).
inline bool penetrates(const World& world, double radius, double x, double y) {
  const Room& room = world.room;
  const double r = radius - kPenetrationTolerance;
  const double x0 = room.origin.x, y0 = room.origin.y;
  if (x < x0 + r || y < y0 + r || x > x0 + room.width - r || y > y0 + room.height - r) {
    return true;
  }
  const geometry::Point2 p{x, y};
  for (const Circle& c : room.circles) {
    const double reach = c.radius + r;
    if (geometry::squaredDistance(p, c.center) < reach * reach) return true;
  }
  for (const Rectangle& box : room.rectangles) {
    if (geometry::squaredDistance(box, p) < r * r) return true;
  }
  return room.map && geometry::blockedWithin(*room.map, p, r);
}

/// The same for a disc of the world's (first) robot's radius.
inline bool penetrates(const World& world, double x, double y) {
  return penetrates(world, world.robot().radius, x, y);
}

/// The largest radius of the world's robots: the room must hold each of them, and the simulator's
/// robot–robot contact looks that far.
double largestRadius(const World& world);

/// Where a node takes the robot's pose from: the world file (roomba_sim, the tools), or elsewhere
/// (tf and requests: roomba_bt and rrt_planner, which must not refuse a map whose (0, 0) is a wall
/// when the simulator was given another pose).
enum class PoseSource { kWorldFile, kElsewhere };

/// Throws util::InvalidInput naming the first bad parameter by its path (e.g. "robot.radius: must
/// be a finite number in (0, 10], got -1", "robots[1].name: repeats 'a'"): values outside
/// WorldLimits, a room smaller than the robot, furniture with a non-positive size, a coverage grid
/// too large for its limits, an initial pose that is not finite or puts the disc into a wall or
/// furniture; for named robots also a bad or repeated name and two robots whose discs overlap.
/// An unnamed robot's initial pose must be free only when the node takes the robot's pose from
/// the world file (`pose`; its coordinates are checked either way).
void validate(const World& world, PoseSource pose = PoseSource::kWorldFile);

/// The room alone (validate()'s room, furniture, map and coverage-grid checks, for a disc of
/// `robot_radius`): what a request that describes a room to plan in must pass, without the
/// robots' rules (their speeds, names and poses).
void validateRoom(const World& world, double robot_radius);

/// Whether a coverage grid of `cell_size` over the world's room stays within WorldLimits (its
/// cells, and the cell × furniture tests at start).
bool coverageGridFits(const World& world, double cell_size);

/// The coverage cell of a world whose file does not set one: World's default (0.025 m), doubled
/// until the grid fits (coverageGridFits): 0.05 m for a 100 × 100 m map, 0.1 m up to 316 m.
double defaultCoverageCellSize(const World& world);

/// Makes `grid` (read from `map_file`, "" when it came in a message) the world's map: the room
/// becomes its known part, and the (first) robot starts at the map's origin (0, 0).
void useMap(World& world, std::shared_ptr<const geometry::OccupancyGrid> grid,
            const std::string& map_file);

/// The world a map makes on its own (a map received on /map): the room is the grid's known
/// part (as for a map file), its occupied and unknown cells are walls, one unnamed robot with
/// `robot_radius` and the other defaults at (0, 0), and the coverage cell is
/// defaultCoverageCellSize(). Not validated.
World mapWorld(std::shared_ptr<const geometry::OccupancyGrid> grid, double robot_radius);

/// `world` cut to `region` (m): its edges become walls (a large map cut to the rooms to clean),
/// and the coverage cell is chosen again for it unless the world file set it. The part kept is
/// whole cells inside the region: its lower-left corner on the map's grid, its size whole
/// coverage cells (up to the room's wall where the region reaches it), so that the cut walls lie
/// between the coverage lattice's points. Throws
/// util::InvalidInput naming `field` when the region is not finite, does not lie within the
/// room (a map's whole extent, unknown border included), or keeps a part of the room no wider
/// and higher than the robot (once in whole cells).
World cropped(World world, const geometry::Rectangle& region, const std::string& field);

}  // namespace roomba_rrt::world
