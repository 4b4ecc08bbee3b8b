// roomba_coverage's command line: what to run (behaviour, duration, seeds, robots, files) and
// what to write (CSV, picture, plot).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace roomba_rrt::tools {

/// roomba_coverage's command line (parseCoverageArguments()); not coverage::CoverageOptions, which
/// says how the planner covers the floor.
struct CoverageArguments {
  std::string behavior;  ///< "fsm", "bt" or "coverage" (the cleaning tree); "" with --compare
  double duration = 600;
  unsigned seed = 1;
  int seeds = 1;
  std::string world = ROOMBA_RRT_CONFIG_DIR "/roomba_world.yaml";
  std::string pose;  ///< --pose X,Y[,THETA]; "" = the world's initial pose
  std::string crop;  ///< --crop X0,Y0,X1,Y1; "" = the whole world
  std::string config = ROOMBA_RRT_CONFIG_DIR "/roomba_behavior.yaml";
  std::string tree;
  std::string csv;
  std::string png;
  std::vector<int> robots;  ///< robot counts (--robots); empty: the world's robots
  std::string plot;
  int lag = 0;       ///< --lag: steps between the simulator's state and what the behaviour sees
  int predict = -1;  ///< --predict: ticks the cleaning tree drives the pose forward; -1: lag
  int predictTicks() const { return predict < 0 ? lag : predict; }
  bool compare = false;  ///< --compare: fsm, bt and coverage side by side
  /// --unknown: the cleaning tree starts with an empty map and its lidar (behaviour "unknown",
  /// explore_clean.h); with --compare a fourth column.
  bool unknown = false;
  /// --known-map: with --unknown, the map the robot is given (a map_server YAML or a world file,
  /// perhaps stale: clean_known_map.h; behaviour "known-map"); "" none.
  std::string known_map;
  /// --sensors: the presets the robot carries instead of the world's sensors (lds, ir_bumper;
  /// empty: none, the bumper alone); unset: the world's.
  std::optional<std::vector<std::string>> sensors;
  bool help = false;  ///< -h or --help: print coverageUsage() and nothing else
};

/// The usage message, one line per flag.
const char* coverageUsage();

/// Parses `--flag value` pairs. Throws std::invalid_argument naming the flag on an unknown flag, a
/// missing or malformed value, or flags that do not go together (--tree without bt or coverage,
/// --csv or --png with --robots, --compare with --behavior, --tree, --csv, --png or --robots).
CoverageArguments parseCoverageArguments(int argc, const char* const* argv);

}  // namespace roomba_rrt::tools
