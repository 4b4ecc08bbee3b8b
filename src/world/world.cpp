#include "roomba_rrt/world/world.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <set>
#include <stdexcept>
#include <utility>

#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/util/require.h"
#include "roomba_rrt/util/text_file.h"
#include "roomba_rrt/util/yaml_reader.h"

namespace roomba_rrt::world {

namespace {

using util::entry;
using util::InvalidInput;
using util::member;
using util::show;

[[noreturn]] void fail(const std::string& field, const std::string& problem) {
  throw InvalidInput(field, problem);
}

using util::requirePositive;

/// Every named coordinate under `prefix` ("initial_pose" + ".x") is within the supported range.
void requireCoordinates(const std::string& prefix,
                        std::initializer_list<std::pair<const char*, double>> values) {
  for (const auto& [key, value] : values) {
    util::requireInRange(member(prefix, key), value, -WorldLimits::kMaxCoordinate,
                         WorldLimits::kMaxCoordinate);
  }
}

/// A YAML mapping read key by key, naming every value by its path ("robot.radius",
/// "furniture.circles[2].x"); finish() rejects the keys nobody asked for (typos).
class Section {
 public:
  Section(const YAML::Node& node, std::string path) : node_(node), path_(std::move(path)) {
    if (node_ && !node_.IsNull() && !node_.IsMap()) fail(name(""), "must be a mapping");
  }
  void finish() const {
    if (!node_ || !node_.IsMap()) return;
    for (const auto& entry : node_) {
      const std::string key = entry.first.as<std::string>();
      if (!known_.count(key)) fail(name(key), "is not a known parameter");
    }
  }
  std::string name(const std::string& key) const {
    return key.empty() ? path_ : member(path_, key);
  }
  YAML::Node child(const std::string& key) {
    known_.insert(key);
    const YAML::Node& node = node_;  // const: a lookup must not insert the key
    return node && node.IsMap() ? node[key] : YAML::Node();
  }
  void read(const std::string& key, double& value) {
    const YAML::Node item = child(key);
    if (!item || item.IsNull()) return;  // missing or empty: keep the default
    try {
      value = item.as<double>();
    } catch (const YAML::Exception&) {
      fail(name(key), "must be a number, got '" + YAML::Dump(item) + "'");
    }
  }

 private:
  YAML::Node node_;
  std::string path_;
  std::set<std::string> known_;
};

template <typename Item, typename ReadItem>
void readList(Section& parent, const std::string& key, std::vector<Item>& items, ReadItem read) {
  const YAML::Node list = parent.child(key);
  if (!list || list.IsNull()) return;
  if (!list.IsSequence()) fail(parent.name(key), "must be a list");
  if (list.size() > WorldLimits::kMaxFurniture) {
    fail(parent.name(key), "has " + std::to_string(list.size()) + " entries; at most " +
                               std::to_string(WorldLimits::kMaxFurniture) + " are supported");
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    Section section(list[i], entry(parent.name(key), i));
    Item item;
    read(section, item);
    section.finish();
    items.push_back(item);
  }
}

/// The room a map makes: its known part (OccupancyGrid::knownExtent()), its edges walls.
void roomOfMap(const geometry::OccupancyGrid& grid, World& world) {
  const geometry::Rectangle known = grid.knownExtent();
  world.origin = {known.min_x, known.min_y};
  world.width = known.max_x - known.min_x;
  world.height = known.max_y - known.min_y;
}

/// The map named by `map:` (relative to the world file's folder): its grid, and the room it
/// makes (its known part). The initial pose defaults to the map's origin (0, 0).
void readMap(const YAML::Node& node, const std::string& source, World& world) {
  if (!node.IsScalar() || node.Scalar().empty()) fail("map", "must be a map_server YAML file");
  std::filesystem::path file = node.Scalar();
  if (file.is_relative() && source != "<string>") {
    file = std::filesystem::path(source).parent_path() / file;
  }
  geometry::MapFile map;
  try {
    map = geometry::loadMap(file.string());
  } catch (const InvalidInput& e) {
    // "map: apartment.yaml: resolution: must be ...": the world's key, then the map's own.
    throw InvalidInput("map", e.what());
  }
  roomOfMap(map.grid, world);
  world.initial_pose = {0.0, 0.0, 0.0};
  world.map_file = file.string();
  world.map = std::make_shared<const geometry::OccupancyGrid>(std::move(map.grid));
}

World readWorld(const YAML::Node& root, const std::string& source) {
  World world;
  Section top(root, "");
  const bool has_map = root.IsMap() && root["map"];
  for (const char* section : {"room", "furniture", "robot", "initial_pose"}) {
    const YAML::Node node = root.IsMap() ? root[section] : YAML::Node();
    if ((!node || node.IsNull()) && !(has_map && std::string(section) == "room")) {
      world.defaulted_sections.push_back(section);
    }
  }
  if (has_map) {
    if (root["room"]) fail("room", "cannot be used with map: the map's extent is the room");
    readMap(top.child("map"), source, world);
  }
  {
    Section room(top.child("room"), "room");
    room.read("width", world.width);
    room.read("height", world.height);
    room.finish();
  }
  {
    Section furniture(top.child("furniture"), "furniture");
    readList(furniture, "circles", world.circles, [](Section& s, Circle& c) {
      s.read("x", c.center.x);
      s.read("y", c.center.y);
      s.read("radius", c.radius);
    });
    readList(furniture, "rectangles", world.rectangles, [](Section& s, Rectangle& b) {
      s.read("min_x", b.min_x);
      s.read("min_y", b.min_y);
      s.read("max_x", b.max_x);
      s.read("max_y", b.max_y);
    });
    furniture.finish();
  }
  {
    Section robot(top.child("robot"), "robot");
    robot.read("radius", world.robot_radius);
    robot.read("max_linear_speed", world.max_linear_speed);
    robot.read("max_angular_speed", world.max_angular_speed);
    robot.finish();
  }
  {
    Section pose(top.child("initial_pose"), "initial_pose");
    pose.read("x", world.initial_pose.x);
    pose.read("y", world.initial_pose.y);
    pose.read("theta", world.initial_pose.theta);
    pose.finish();
  }
  {
    // Named robots: pose each, radius and speed limits each or the shared `robot:` values.
    const bool shared_pose = top.child("initial_pose") && !top.child("initial_pose").IsNull();
    readList(top, "robots", world.robots, [&world](Section& s, RobotSpec& r) {
      const YAML::Node name = s.child("name");
      if (!name || !name.IsScalar()) fail(s.name("name"), "is required (a string)");
      r.name = name.as<std::string>();
      Section pose(s.child("initial_pose"), s.name("initial_pose"));
      r.initial_pose = world.initial_pose;
      pose.read("x", r.initial_pose.x);
      pose.read("y", r.initial_pose.y);
      pose.read("theta", r.initial_pose.theta);
      pose.finish();
      r.radius = world.robot_radius;
      r.max_linear_speed = world.max_linear_speed;
      r.max_angular_speed = world.max_angular_speed;
      s.read("radius", r.radius);
      s.read("max_linear_speed", r.max_linear_speed);
      s.read("max_angular_speed", r.max_angular_speed);
    });
    if (shared_pose && !world.robots.empty()) {
      fail("initial_pose", "cannot be used with robots: give each robot its own initial_pose");
    }
  }
  top.read("step", world.step);
  world.coverage_cell_size_given = root.IsMap() && root["coverage_cell_size"];
  if (world.coverage_cell_size_given) {
    top.read("coverage_cell_size", world.coverage_cell_size);
  } else {  // a large map still loads: with coarser cells
    world.coverage_cell_size = defaultCoverageCellSize(world);
  }
  top.read("command_timeout", world.command_timeout);
  top.read("real_time_factor", world.real_time_factor);
  top.finish();
  return world;
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
    requirePositive(member(prefix, "radius"), r.radius, WorldLimits::kMaxRobotRadius);
    requirePositive(member(prefix, "max_linear_speed"), r.max_linear_speed, WorldLimits::kMaxSpeed);
    requirePositive(member(prefix, "max_angular_speed"), r.max_angular_speed,
                    WorldLimits::kMaxSpeed);
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
  return std::ceil(world.width / cell_size) * std::ceil(world.height / cell_size);
}

std::size_t furnitureCount(const World& world) {
  return world.circles.size() + world.rectangles.size();
}

}  // namespace

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
  requirePositive("room.width", world.width, L::kMaxRoomSize);
  requirePositive("room.height", world.height, L::kMaxRoomSize);
  requirePositive("robot.radius", world.robot_radius, L::kMaxRobotRadius);
  requirePositive("robot.max_linear_speed", world.max_linear_speed, L::kMaxSpeed);
  requirePositive("robot.max_angular_speed", world.max_angular_speed, L::kMaxSpeed);
  util::requireInRange("step", world.step, L::kMinStep, L::kMaxStep);
  util::requireInRange("coverage_cell_size", world.coverage_cell_size, L::kMinCellSize, 1.0);
  requirePositive("command_timeout", world.command_timeout, L::kMaxCommandTimeout);
  util::requireInRange("real_time_factor", world.real_time_factor, L::kMinRealTimeFactor,
                       L::kMaxRealTimeFactor);
  const std::size_t furniture = furnitureCount(world);
  if (furniture > L::kMaxFurniture) {
    fail("furniture", "has " + std::to_string(furniture) + " pieces; at most " +
                          std::to_string(L::kMaxFurniture) + " are supported");
  }
  if (!coverageGridFits(world, world.coverage_cell_size)) {
    const double cells = coverageCells(world, world.coverage_cell_size);
    fail("coverage_cell_size",
         "(" + show(world.coverage_cell_size) + ") is too small for a " + show(world.width) +
             " x " + show(world.height) + " m room with " + std::to_string(furniture) +
             " pieces of furniture: " + show(cells) + " cells, at most " +
             show(std::min(L::kMaxCoverageCells, L::kMaxGridWork / (1.0 + furniture))) +
             " are supported");
  }
  for (const auto& [name, size] :
       {std::pair{"room.width", world.width}, {"room.height", world.height}}) {
    const double diameter = 2 * world.robot_radius;
    if (size <= diameter) {
      fail(name, "(" + show(size) + ") must exceed the robot's diameter " + show(diameter));
    }
  }
  if (world.max_linear_speed * world.step >= world.robot_radius) {
    fail("step", "is too long: the robot would move more than its radius in one step");
  }
  for (std::size_t i = 0; i < world.circles.size(); ++i) {
    const Circle& c = world.circles[i];
    const std::string name = entry("furniture.circles", i);
    requireCoordinates(name, {{"x", c.center.x}, {"y", c.center.y}});
    requirePositive(member(name, "radius"), c.radius, WorldLimits::kMaxRoomSize);
  }
  for (std::size_t i = 0; i < world.rectangles.size(); ++i) {
    const Rectangle& b = world.rectangles[i];
    const std::string name = entry("furniture.rectangles", i);
    requireCoordinates(
        name, {{"min_x", b.min_x}, {"min_y", b.min_y}, {"max_x", b.max_x}, {"max_y", b.max_y}});
    if (!(b.max_x > b.min_x)) fail(member(name, "max_x"), "must be greater than min_x");
    if (!(b.max_y > b.min_y)) fail(member(name, "max_y"), "must be greater than min_y");
  }
  const robot::Pose2D& p = world.initial_pose;
  requireCoordinates("initial_pose", {{"x", p.x}, {"y", p.y}, {"theta", p.theta}});  // |v| ≤ 1e4
  if (pose == PoseSource::kWorldFile && world.robots.empty() && penetrates(world, p.x, p.y)) {
    fail("initial_pose",
         "(" + show(p.x) + ", " + show(p.y) +
             ") puts the robot's disc inside a wall or a piece of " +
             (world.map ? "furniture, or on a blocked cell of the map: give the robot a free "
                          "initial_pose (x, y)"
                        : "furniture"));
  }
  validateRobots(world);
}

std::vector<RobotSpec> robotsOf(const World& world) {
  if (!world.robots.empty()) return world.robots;
  return {RobotSpec{"", world.initial_pose, world.robot_radius, world.max_linear_speed,
                    world.max_angular_speed}};
}

namespace {
/// Reads and validates; every message starts with `source` (the file) and names the parameter.
/// The YAML of a world file (duplicate keys refused), errors naming `source`.
YAML::Node parseText(const std::string& yaml_text, const std::string& source) {
  try {
    return util::parseYaml(yaml_text);
  } catch (const InvalidInput& e) {
    throw e.in(source);
  }
}

World buildWorld(const YAML::Node& root, const std::string& source, bool check = true) {
  try {
    World world = readWorld(root, source);
    if (check) validate(world);
    return world;
  } catch (const InvalidInput& e) {
    throw e.in(source);
  } catch (const YAML::Exception& e) {
    throw InvalidInput("", e.what(), source);
  }
}
}  // namespace

World parseWorld(const std::string& yaml_text, const std::string& source) {
  if (yaml_text.size() > WorldLimits::kMaxFileBytes) {
    throw InvalidInput("",
                       "the world has " + std::to_string(yaml_text.size()) + " bytes; at most " +
                           std::to_string(WorldLimits::kMaxFileBytes) + " are supported",
                       source);
  }
  return buildWorld(parseText(yaml_text, source), source);
}

World mapWorld(std::shared_ptr<const geometry::OccupancyGrid> grid, double robot_radius) {
  World world;
  roomOfMap(*grid, world);
  world.initial_pose = {0.0, 0.0, 0.0};
  world.map = std::move(grid);
  world.robot_radius = robot_radius;
  world.coverage_cell_size = defaultCoverageCellSize(world);
  return world;
}

World cropped(World world, const geometry::Rectangle& region, const std::string& field) {
  // A map's whole extent may be named (its unknown border too); what is kept is the room's part.
  const geometry::Rectangle room{world.origin.x, world.origin.y, world.origin.x + world.width,
                                 world.origin.y + world.height};
  const geometry::Rectangle world_box = world.map ? world.map->extent() : room;
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
  if (world.map) {
    const geometry::OccupancyGrid& grid = *world.map;
    const auto onGrid = [&](double v, double grid_origin) {
      return grid_origin +
             std::ceil((v - grid_origin) / grid.resolution - kSlack) * grid.resolution;
    };
    corner = {onGrid(corner.x, grid.origin.x), onGrid(corner.y, grid.origin.y)};
  }
  const geometry::Point2 far{std::min(r.max_x, room.max_x), std::min(r.max_y, room.max_y)};
  world.origin = corner;
  world.width = far.x - corner.x;
  world.height = far.y - corner.y;
  if (!world.coverage_cell_size_given) {  // the region's own: a crop of a large map is finer
    world.coverage_cell_size = defaultCoverageCellSize(world);
  }
  const double cell = world.coverage_cell_size;
  const auto wholeCells = [&](double size, bool to_wall) {
    return to_wall ? size : std::floor(size / cell + kSlack) * cell;
  };
  world.width = wholeCells(world.width, far.x >= room.max_x);
  world.height = wholeCells(world.height, far.y >= room.max_y);
  // Whole cells only shrink the part kept: one test covers the region as asked and as kept.
  if (!(world.width > 2 * world.robot_radius && world.height > 2 * world.robot_radius)) {
    throw refuse();
  }
  return world;
}

World loadWorld(const std::string& yaml_path, PoseSource pose) {
  World world = readWorldFile(yaml_path);
  try {
    validate(world, pose);
  } catch (const InvalidInput& e) {
    throw e.in(yaml_path);
  }
  return world;
}

World readWorldFile(const std::string& yaml_path) {
  if (geometry::isMapYaml(yaml_path)) {
    // A map_server YAML given as the world: the map with every other default.
    YAML::Node root;
    root["map"] = std::filesystem::path(yaml_path).filename().string();
    return buildWorld(root, yaml_path, /*check=*/false);
  }
  const std::string text = util::readTextFile(yaml_path, WorldLimits::kMaxFileBytes, "world file");
  return buildWorld(parseText(text, yaml_path), yaml_path, /*check=*/false);
}

std::string defaultsNotice(const World& world, const std::string& source) {
  std::string sections, keys;
  const auto add = [&keys](const std::string& key, double value) {
    keys += (keys.empty() ? "" : ", ") + key + " " + util::show(value);
  };
  for (const std::string& section : world.defaulted_sections) {
    if (section == "initial_pose" && !world.robots.empty()) continue;  // each robot has its own
    sections += (sections.empty() ? "" : ", ") + section;
    if (section == "room") {
      add("room.width", world.width);
      add("room.height", world.height);
    } else if (section == "furniture") {
      keys += std::string(keys.empty() ? "" : ", ") + "no furniture";
    } else if (section == "robot") {
      add("robot.radius", world.robot_radius);
      add("robot.max_linear_speed", world.max_linear_speed);
      add("robot.max_angular_speed", world.max_angular_speed);
    } else if (section == "initial_pose") {
      add("initial_pose.x", world.initial_pose.x);
      add("initial_pose.y", world.initial_pose.y);
      add("initial_pose.theta", world.initial_pose.theta);
    }
  }
  return sections.empty()
             ? ""
             : source + " sets no " + sections + ": the defaults are used (" + keys + ")";
}

}  // namespace roomba_rrt::world
