// Reading a world file (world_file.h): the YAML read key by key into a World and the simulator's
// settings, then validated.
#include "roomba_rrt/world/world_file.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
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

[[noreturn]] void fail(const std::string& field, const std::string& problem) {
  throw InvalidInput(field, problem);
}

/// A YAML mapping read key by key, naming every value by its path ("robot.radius",
/// "furniture.circles[2].x"); finish() rejects the keys nobody asked for (typos). A key that is
/// absent keeps its default; a key that is present must have a value (`min_y:` or `min_y: ~`
/// is refused naming it, not read as 0 or as the default).
class Section {
 public:
  Section(const YAML::Node& node, std::string path) : node_(node), path_(std::move(path)) {
    if (node_ && node_.IsNull() && !path_.empty()) fail(path_, "has no value; give a mapping");
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
    return node && node.IsMap() ? node[key] : YAML::Node(YAML::NodeType::Undefined);
  }
  void read(const std::string& key, double& value) {
    const YAML::Node item = child(key);
    if (!item) return;  // missing: keep the default
    if (item.IsNull()) fail(name(key), "has no value; give a number or remove the key");
    try {
      value = item.as<double>();
    } catch (const YAML::Exception&) {
      fail(name(key), "must be a number, got '" + YAML::Dump(item) + "'");
    }
  }
  /// read(), for a value that has no default (a piece of furniture's coordinates).
  void need(const std::string& key, double& value) {
    if (!child(key)) fail(name(key), "is missing");
    read(key, value);
  }

 private:
  YAML::Node node_;
  std::string path_;
  std::set<std::string> known_;
};

template <typename Item, typename ReadItem>
void readList(Section& parent, const std::string& key, std::vector<Item>& items, ReadItem read) {
  const YAML::Node list = parent.child(key);
  if (!list) return;
  if (list.IsNull()) fail(parent.name(key), "has no value; give a list or remove the key");
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
  useMap(world, std::make_shared<const geometry::OccupancyGrid>(std::move(map.grid)),
         file.string());
}

/// The robot's size and speed limits under `section`.
void readRobotLimits(Section& section, RobotSpec& robot) {
  section.read("radius", robot.radius);
  section.read("max_linear_speed", robot.max_linear_speed);
  section.read("max_angular_speed", robot.max_angular_speed);
}

/// A whole number under `key` (read as a number, then required whole and within [lo, hi]).
template <typename Int>
void readWhole(Section& section, const std::string& key, Int& value, double lo, double hi) {
  double number = static_cast<double>(value);
  section.read(key, number);
  if (!(number >= lo && number <= hi) || number != std::floor(number)) {
    fail(section.name(key), "must be a whole number in [" + util::show(lo) + ", " + util::show(hi) +
                                "], got " + util::show(number));
  }
  value = static_cast<Int>(number);
}

/// A string under `key`; false (and `value` kept) when it is missing.
bool readText(Section& section, const std::string& key, std::string& value) {
  const YAML::Node item = section.child(key);
  if (!item || item.IsNull()) return false;
  if (!item.IsScalar()) fail(section.name(key), "must be a string");
  value = item.Scalar();
  return true;
}

/// The `sensors:` list under `section` (a robot of `radius`): each entry starts from its
/// `preset:` (lds unless it names ir_bumper), then takes the keys it sets; a `name:` without a
/// `frame:` gets the frame base_<name>. Missing, `sensors` is kept; null or [] means none.
void readSensors(Section& section, double radius, std::vector<sensors::RangeSensorSpec>& out) {
  const YAML::Node list = section.child("sensors");
  if (!list) return;
  const std::string field = section.name("sensors");
  out.clear();
  if (list.IsNull()) return;
  if (!list.IsSequence()) fail(field, "must be a list");
  if (list.size() > sensors::SensorLimits::kMaxSensors) {
    fail(field, "has " + std::to_string(list.size()) + " entries; at most " +
                    std::to_string(sensors::SensorLimits::kMaxSensors) + " are supported");
  }
  for (std::size_t k = 0; k < list.size(); ++k) {
    Section s(list[k], entry(field, k));
    std::string preset = "lds";
    readText(s, "preset", preset);
    sensors::RangeSensorSpec spec = sensors::preset(preset, radius, s.name("preset"));
    if (readText(s, "name", spec.name)) spec.frame = "base_" + spec.name;
    readText(s, "frame", spec.frame);
    s.read("x", spec.mount.x);
    s.read("y", spec.mount.y);
    s.read("yaw", spec.mount.theta);
    s.read("angle_min", spec.angle_min);
    s.read("angle_max", spec.angle_max);
    readWhole(s, "samples", spec.samples, 0, 1e9);
    s.read("range_min", spec.range_min);
    s.read("range_max", spec.range_max);
    s.read("rate", spec.rate);
    s.read("noise_stddev", spec.noise_stddev);
    readWhole(s, "seed", spec.seed, 0, 4294967295.0);
    s.finish();
    out.push_back(spec);
  }
}

/// An initial pose under `section` (missing keys keep `pose`'s).
void readPose(Section& section, robot::Pose2D& pose) {
  section.read("x", pose.x);
  section.read("y", pose.y);
  section.read("theta", pose.theta);
}

WorldFile readWorld(const YAML::Node& root, const std::string& source) {
  WorldFile file;
  World& world = file.world;
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
    room.read("width", world.room.width);
    room.read("height", world.room.height);
    room.finish();
  }
  {
    Section furniture(top.child("furniture"), "furniture");
    readList(furniture, "circles", world.room.circles, [](Section& s, Circle& c) {
      s.need("x", c.center.x);
      s.need("y", c.center.y);
      s.need("radius", c.radius);
    });
    readList(furniture, "rectangles", world.room.rectangles, [](Section& s, Rectangle& b) {
      s.need("min_x", b.min_x);
      s.need("min_y", b.min_y);
      s.need("max_x", b.max_x);
      s.need("max_y", b.max_y);
    });
    furniture.finish();
  }
  // `robot:` and `initial_pose:` describe the one unnamed robot, or (`robot:` only) the
  // defaults of every named robot under `robots:`.
  RobotSpec shared = world.robot();  // the defaults, at a map's origin for a map world
  {
    Section robot(top.child("robot"), "robot");
    readRobotLimits(robot, shared);
    robot.finish();
  }
  // `sensors:` are the unnamed robot's, or every named robot's unless its entry has its own.
  // None named: the LDS preset, at most as fast as the simulator steps.
  top.read("step", world.step);  // first: a slow simulator (step > 0.2 s) slows the preset
  shared.sensors = {sensors::ldsPreset()};
  if (world.step > 0) shared.sensors[0].rate = std::min(shared.sensors[0].rate, 1 / world.step);
  readSensors(top, shared.radius, shared.sensors);
  {
    Section pose(top.child("initial_pose"), "initial_pose");
    readPose(pose, shared.initial_pose);
    pose.finish();
  }
  {
    const bool shared_pose = top.child("initial_pose") && !top.child("initial_pose").IsNull();
    std::vector<RobotSpec> named;
    readList(top, "robots", named, [&shared](Section& s, RobotSpec& r) {
      const YAML::Node name = s.child("name");
      if (!name || !name.IsScalar()) fail(s.name("name"), "is required (a string)");
      r = shared;
      r.name = name.as<std::string>();
      Section pose(s.child("initial_pose"), s.name("initial_pose"));
      readPose(pose, r.initial_pose);
      pose.finish();
      readRobotLimits(s, r);
      readSensors(s, r.radius, r.sensors);
    });
    if (shared_pose && !named.empty()) {
      fail("initial_pose", "cannot be used with robots: give each robot its own initial_pose");
    }
    world.robots = named.empty() ? std::vector<RobotSpec>{shared} : std::move(named);
  }
  top.read("step", world.step);
  world.coverage_cell_size_given = root.IsMap() && root["coverage_cell_size"];
  if (world.coverage_cell_size_given) {
    top.read("coverage_cell_size", world.coverage_cell_size);
  } else {  // a large map still loads: with coarser cells
    world.coverage_cell_size = defaultCoverageCellSize(world);
  }
  top.read("command_timeout", file.simulator.command_timeout);
  top.read("real_time_factor", file.simulator.real_time_factor);
  top.finish();
  return file;
}

/// The YAML of a world file (duplicate keys refused), errors naming `source`.
YAML::Node parseText(const std::string& yaml_text, const std::string& source) {
  try {
    return util::parseYaml(yaml_text);
  } catch (const InvalidInput& e) {
    throw e.in(source);
  }
}

/// Reads (and with `check`, validates); every message starts with `source` (the file) and names
/// the parameter.
WorldFile buildWorld(const YAML::Node& root, const std::string& source, bool check = true) {
  try {
    WorldFile file = readWorld(root, source);
    if (check) {
      validate(file.world);
      validate(file.simulator);
    }
    return file;
  } catch (const InvalidInput& e) {
    throw e.in(source);
  } catch (const YAML::Exception& e) {
    throw InvalidInput("", e.what(), source);
  }
}

}  // namespace

void validate(const SimulatorSettings& settings) {
  using S = SimulatorSettings;
  util::requirePositive("command_timeout", settings.command_timeout, S::kMaxCommandTimeout);
  util::requireInRange("real_time_factor", settings.real_time_factor, S::kMinRealTimeFactor,
                       S::kMaxRealTimeFactor);
}

World parseWorld(const std::string& yaml_text, const std::string& source) {
  if (yaml_text.size() > WorldLimits::kMaxFileBytes) {
    throw InvalidInput("",
                       "the world has " + std::to_string(yaml_text.size()) + " bytes; at most " +
                           std::to_string(WorldLimits::kMaxFileBytes) + " are supported",
                       source);
  }
  return buildWorld(parseText(yaml_text, source), source).world;
}

World loadWorld(const std::string& yaml_path, PoseSource pose) {
  WorldFile file = readWorldFile(yaml_path);
  try {
    validate(file.world, pose);
    validate(file.simulator);
  } catch (const InvalidInput& e) {
    throw e.in(yaml_path);
  }
  return std::move(file.world);
}

WorldFile readWorldFile(const std::string& yaml_path) {
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
  // A section left out gave the defaults: the unnamed robot's own values, or (named robots) the
  // defaults each of them started from.
  const RobotSpec robot = world.namedRobots() ? RobotSpec{} : world.robot();
  for (const std::string& section : world.defaulted_sections) {
    if (section == "initial_pose" && world.namedRobots()) continue;  // each robot has its own
    sections += (sections.empty() ? "" : ", ") + section;
    if (section == "room") {
      add("room.width", world.room.width);
      add("room.height", world.room.height);
    } else if (section == "furniture") {
      keys += std::string(keys.empty() ? "" : ", ") + "no furniture";
    } else if (section == "robot") {
      add("robot.radius", robot.radius);
      add("robot.max_linear_speed", robot.max_linear_speed);
      add("robot.max_angular_speed", robot.max_angular_speed);
    } else if (section == "initial_pose") {
      add("initial_pose.x", robot.initial_pose.x);
      add("initial_pose.y", robot.initial_pose.y);
      add("initial_pose.theta", robot.initial_pose.theta);
    }
  }
  return sections.empty()
             ? ""
             : source + " sets no " + sections + ": the defaults are used (" + keys + ")";
}

}  // namespace roomba_rrt::world
