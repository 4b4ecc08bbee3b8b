// The simulated world: a rectangular room, furniture (circles and axis-aligned rectangles) and the
// robot's physical parameters, loaded from YAML (config/roomba_world.yaml documents the format).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "roomba_rrt/geometry/geometry.h"
#include "roomba_rrt/geometry/occupancy_grid.h"
#include "roomba_rrt/robot/robot_state.h"

namespace roomba_rrt::world {

/// Furniture: round pieces (a table leg, a bin) and axis-aligned rectangular ones (a sofa, a
/// cupboard), in metres; the shapes of the shared geometry module, which the planner uses too.
using geometry::Circle;
using geometry::Rectangle;

/// At most this many robots under `robots:`.
constexpr std::size_t kMaxRobots = 1000;

/// One robot of a world that lists several under `robots:`. Radius and speed limits default to the
/// world's shared `robot:` values.
struct RobotSpec {
  std::string name;  ///< namespace and tf prefix: a letter, then letters, digits or '_'
  robot::Pose2D initial_pose{3.2, 2.4, 0.0};
  double radius = 0.17;            ///< m
  double max_linear_speed = 1.0;   ///< m/s
  double max_angular_speed = 2.0;  ///< rad/s
};

/// Everything the simulator needs to know about the room and the robot. Defaults are the lab's
/// simulation: a 6.4 m × 4.8 m empty room, a 0.17 m Roomba at the centre facing +x, 1.0 m/s and
/// 2.0 rad/s speed limits, steps of 1/60 s.
struct World {
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

  double robot_radius = 0.17;      ///< m
  double max_linear_speed = 1.0;   ///< |v| is clamped to this, m/s
  double max_angular_speed = 2.0;  ///< |w| is clamped to this, rad/s
  double step = 1.0 / 60.0;        ///< integration step, s
  robot::Pose2D initial_pose{3.2, 2.4, 0.0};

  /// Edge of a coverage grid cell, m. A world file that does not set it gets
  /// defaultCoverageCellSize(): this, or coarser for a world too large for it.
  double coverage_cell_size = 0.025;
  /// The world file set coverage_cell_size (false: the default chose it, and a tool that keeps
  /// a region of the world chooses again for the region).
  bool coverage_cell_size_given = false;
  double command_timeout = 0.5;   ///< node: stop when no command arrived for this long, s
  double real_time_factor = 1.0;  ///< node: simulated seconds per wall-clock second

  /// Named robots (`robots:` in YAML). Empty: one unnamed robot with the fields above, exactly
  /// the lab's simulation. When given, `initial_pose` is not used.
  std::vector<RobotSpec> robots;

  /// The sections (room, furniture, robot, initial_pose) the world file did not set at all, in
  /// that order: their keys have the defaults above (see defaultsNotice()).
  std::vector<std::string> defaulted_sections;
};

/// The supported ranges (validate() refuses anything outside them, naming the parameter). They
/// keep every computation finite and the coverage grid's memory and set-up time small.
struct WorldLimits {
  static constexpr double kMaxRoomSize = 1000;        ///< room.width, room.height ≤ this, m
  static constexpr double kMaxRobotRadius = 10;       ///< m
  static constexpr double kMaxSpeed = 100;            ///< m/s and rad/s
  static constexpr double kMinStep = 1e-4;            ///< s
  static constexpr double kMaxStep = 1;               ///< s
  static constexpr double kMinCellSize = 1e-3;        ///< coverage_cell_size ≥ this, m
  static constexpr double kMaxCoverageCells = 1e7;    ///< cells in the grid (2.5 MB of bits)
  static constexpr double kMaxGridWork = 5e7;         ///< cells × (1 + furniture) at start
  static constexpr std::size_t kMaxFurniture = 1000;  ///< circles + rectangles
  static constexpr double kMaxCoordinate = 1e4;       ///< |furniture, pose coordinates|, m
  static constexpr double kMaxCommandTimeout = 1e6;   ///< s
  static constexpr double kMinRealTimeFactor = 1e-4;
  static constexpr double kMaxRealTimeFactor = 1e4;
  static constexpr std::size_t kMaxFileBytes = 1 << 20;  ///< a world file is at most 1 MiB
};

/// Overlap below this (m) is floating-point rounding of a push-back, not penetration.
constexpr double kPenetrationTolerance = 1e-9;

/// True when a disc of `radius` centred at (x, y) overlaps a wall, a piece of furniture or a
/// blocked map cell by more than kPenetrationTolerance (where a robot may not be: validate() and
/// the simulator's contact).
inline bool penetrates(const World& world, double radius, double x, double y) {
  const double r = radius - kPenetrationTolerance;
  const double x0 = world.origin.x, y0 = world.origin.y;
  if (x < x0 + r || y < y0 + r || x > x0 + world.width - r || y > y0 + world.height - r) {
    return true;
  }
  const geometry::Point2 p{x, y};
  for (const Circle& c : world.circles) {
    const double reach = c.radius + r;
    if (geometry::squaredDistance(p, c.center) < reach * reach) return true;
  }
  for (const Rectangle& box : world.rectangles) {
    if (geometry::squaredDistance(box, p) < r * r) return true;
  }
  return world.map && geometry::blockedWithin(*world.map, p, r);
}

/// The same for a disc of the world's robot_radius.
inline bool penetrates(const World& world, double x, double y) {
  return penetrates(world, world.robot_radius, x, y);
}

/// The robots a simulator holds: `world.robots`, or when it is empty the one unnamed robot
/// (name "") made of robot_radius, the speed limits and initial_pose.
std::vector<RobotSpec> robotsOf(const World& world);

/// Where a node takes the robot's pose from: the world file (roomba_sim, the tools), or elsewhere
/// (tf and requests: roomba_bt and rrt_planner, which must not refuse a map whose (0, 0) is a wall
/// when the simulator was given another pose).
enum class PoseSource { kWorldFile, kElsewhere };

/// Throws util::InvalidInput naming the first bad parameter by its path (e.g. "robot.radius: must
/// be a finite number in (0, 10], got -1", "robots[1].name: repeats 'a'"): values outside
/// WorldLimits, a room smaller than the robot, furniture with a non-positive size, a coverage grid
/// too large for its limits, an initial pose that is not finite or puts the disc into a wall or
/// furniture; for named robots also a bad or repeated name and two robots whose discs overlap.
/// The single robot's initial pose must be free only when the node takes the robot's pose from
/// the world file (`pose`; its coordinates are checked either way).
void validate(const World& world, PoseSource pose = PoseSource::kWorldFile);

/// Whether a coverage grid of `cell_size` over the world's room stays within WorldLimits (its
/// cells, and the cell × furniture tests at start).
bool coverageGridFits(const World& world, double cell_size);

/// The coverage cell of a world whose file does not set one: World's default (0.025 m), doubled
/// until the grid fits (coverageGridFits): 0.05 m for a 100 × 100 m map, 0.1 m up to 316 m.
double defaultCoverageCellSize(const World& world);

/// The world a map makes on its own (a map received on /map): the room is the grid's known
/// part (as for a map file), its occupied and unknown cells are walls, the robot has
/// `robot_radius` and the other defaults, and the coverage cell is defaultCoverageCellSize().
/// Not validated.
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

/// Reads a world from a YAML file (format: config/roomba_world.yaml); missing keys keep the
/// defaults above. Throws util::InvalidInput naming the file and the bad parameter, for a
/// path that is not a readable regular file, a file larger than WorldLimits::kMaxFileBytes, a value
/// of the wrong type, an unknown key or a world that fails validate().
World loadWorld(const std::string& yaml_path, PoseSource pose = PoseSource::kWorldFile);

/// loadWorld without validate(), for a caller that overrides values before it validates them
/// itself (roomba_sim's private parameters: a map world's ~initial_pose). Still refuses what
/// cannot be read (the file, its keys and types, the map).
World readWorldFile(const std::string& yaml_path);

/// Same as loadWorld, from YAML text (used by tests); `source` names it in error messages.
World parseWorld(const std::string& yaml_text, const std::string& source = "<string>");

/// What a world read from `source` took from the defaults, for the node to say at start-up:
/// "world.yaml sets no room, robot: room.width 6.4, room.height 4.8, robot.radius 0.17, ...",
/// or "" when the file set every section.
std::string defaultsNotice(const World& world, const std::string& source);

}  // namespace roomba_rrt::world
