// Command-line flags shared by the tools (rrt_monte_carlo and rrt_plot share the planner's;
// roomba_coverage parses its numbers the same way). Part of the tools' library, roomba_tools:
// the core libraries know nothing of command lines or of where the source tree is.
#pragma once

#include <map>
#include <set>
#include <string>

#include "roomba_rrt/planning/planner_options.h"
#include "roomba_rrt/planning/problem.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::tools {

/// config/rrt_scenarios.yaml of the source tree the tools were built from.
std::string defaultScenarioFile();

/// A --world value as scripts/run takes it: `empty` (the lab's room, config/roomba_world.yaml),
/// `furnished` (config/roomba_world_furnished.yaml), `apartment` (config/maps/apartment.yaml, a
/// map), or a world file's path (unchanged).
std::string worldFile(const std::string& value);

/// The world of a tool's --world file with --pose "X,Y" or "X,Y,THETA" (m, rad; "" keeps the
/// file's initial pose: a map's (0, 0)) as the robot's initial pose, validated. Throws
/// util::InvalidInput naming the file and the field; a pose in a wall says to pass --pose.
/// `crop` ("X0,Y0,X1,Y1", m; empty: none) keeps that region of the world: its edges become the
/// walls (a large map cut to a room or two).
world::World loadToolWorld(const std::string& file, const std::string& pose,
                           const std::string& crop = "");

/// "X,Y" of a flag: throws std::invalid_argument naming the flag otherwise.
planning::Point2 parsePointFlag(const std::string& flag, const std::string& value);

/// The tools' flags of a planning problem in a world: --world FILE (a world file or a
/// map_server YAML; empty, furnished and apartment name the package's) or --map FILE (a
/// map_server YAML), from --start X,Y to --goal X,Y (both required): the room's walls and
/// furniture or the map's occupied and unknown cells, and the world's robot (a map's: the
/// Roomba's 0.17 m). `name` is set to "room" or "map". Throws std::invalid_argument or
/// util::InvalidInput naming the flag or the file's field.
planning::Problem worldProblem(std::map<std::string, std::string>& tool, std::string* name);

/// What the tools' common flags set.
struct ToolArguments {
  std::string scenario = "a";        ///< --scenario NAME
  std::string scenario_file;         ///< --scenarios FILE (default: defaultScenarioFile())
  planning::PlannerOptions options;  ///< --algorithm --collision --nearest --step --goal-bias
                                     ///< --max-iterations --goal-tolerance --seed --smooth
                                     ///< --random-stream
  std::map<std::string, std::string> tool;  ///< the tool's own flags ("--runs" -> "200")
  bool random_stream_given = false;         ///< --random-stream was on the command line
};

/// worldProblem() of args.tool; and the fast stream unless --random-stream chose one (a room or
/// a map is no lab scenario: there is no MATLAB stream to match).
planning::Problem worldProblem(ToolArguments& args, std::string* name);

/// Parses `--flag value` pairs and the switches `--smooth` and the tool's `switches` (stored as
/// "1"). `tool_flags` are the tool's own flags that take a value. Throws std::invalid_argument
/// with a message naming the flag on an unknown flag, a missing value or a malformed value.
ToolArguments parseToolArguments(int argc, const char* const* argv,
                                 const std::set<std::string>& tool_flags,
                                 const std::set<std::string>& switches);

/// The flags parseToolArguments() knows, one per line, for a usage message.
std::string commonFlagsHelp();

/// std::stoi / std::stod that accept only a whole, finite number; throw naming `flag`.
int parseIntFlag(const std::string& flag, const std::string& value);
double parseDoubleFlag(const std::string& flag, const std::string& value);

}  // namespace roomba_rrt::tools
