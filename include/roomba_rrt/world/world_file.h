// Reading a world file (format: config/roomba_world.yaml): the YAML read key by key, every value
// named by its path in errors ("robot.radius", "furniture.circles[2].x"), unknown keys refused,
// then validated (world.h's validate()). A map_server YAML is a world file too: the map, with
// every other default.
#pragma once

#include <string>

#include "roomba_rrt/world/world.h"

namespace roomba_rrt::world {

/// What a world file may also set for roomba_sim alone: the defaults of its ~command_timeout and
/// ~real_time_factor. The node's settings, not the world's, which every node shares.
struct SimulatorSettings {
  double command_timeout = 0.5;   ///< s without a command before the robot stops
  double real_time_factor = 1.0;  ///< simulated seconds per wall-clock second

  static constexpr double kMaxCommandTimeout = 1e6;  ///< s
  static constexpr double kMinRealTimeFactor = 1e-4;
  static constexpr double kMaxRealTimeFactor = 1e4;
};

/// Throws util::InvalidInput naming the setting outside its range ("real_time_factor: must be in
/// [0.0001, 10000], got 1e+05").
void validate(const SimulatorSettings& settings);

/// A world file as read: the world, and what it sets for the simulator.
struct WorldFile {
  World world;
  SimulatorSettings simulator;
};

/// Reads a world from a YAML file; missing keys keep the defaults of world.h. Throws
/// util::InvalidInput naming the file and the bad parameter, for a path that is not a readable
/// regular file, a file larger than WorldLimits::kMaxFileBytes, a value of the wrong type, an
/// unknown key, or a world (or simulator setting) that fails validate().
World loadWorld(const std::string& yaml_path, PoseSource pose = PoseSource::kWorldFile);

/// The world and simulator settings of a file, without validate(), for a caller that overrides
/// values before it validates them itself (roomba_sim's private parameters: a map world's
/// ~initial_pose). Still refuses what cannot be read (the file, its keys and types, the map).
WorldFile readWorldFile(const std::string& yaml_path);

/// Same as loadWorld, from YAML text (used by tests); `source` names it in error messages.
World parseWorld(const std::string& yaml_text, const std::string& source = "<string>");

/// What a world read from `source` took from the defaults, for the node to say at start-up:
/// "world.yaml sets no room, robot: room.width 6.4, room.height 4.8, robot.radius 0.17, ...",
/// or "" when the file set every section.
std::string defaultsNotice(const World& world, const std::string& source);

}  // namespace roomba_rrt::world
