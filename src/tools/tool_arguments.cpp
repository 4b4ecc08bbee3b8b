#include "tool_arguments.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/world/world_file.h"
#include "roomba_rrt/world_planning/room_problem.h"

namespace roomba_rrt::tools {
namespace {

[[noreturn]] void bad(const std::string& flag, const std::string& why) {
  throw std::invalid_argument(flag + ": " + why);
}

template <typename Enum>
Enum parseEnumFlag(const std::string& flag, const std::string& value,
                   std::optional<Enum> (*parse)(const std::string&)) {
  const auto parsed = parse(value);
  if (!parsed) bad(flag, "unknown value '" + value + "'");
  return *parsed;
}

/// "A,B,C" of a flag as numbers (each whole and finite: parseDoubleFlag).
std::vector<double> parseNumbers(const std::string& flag, const std::string& value) {
  std::vector<double> numbers;
  std::size_t begin = 0;
  while (begin <= value.size()) {
    const std::size_t comma = std::min(value.find(',', begin), value.size());
    numbers.push_back(parseDoubleFlag(flag, value.substr(begin, comma - begin)));
    begin = comma + 1;
  }
  return numbers;
}
}  // namespace

std::string defaultScenarioFile() { return ROOMBA_RRT_CONFIG_DIR "/rrt_scenarios.yaml"; }

std::string worldFile(const std::string& value) {
  if (value == "empty") return ROOMBA_RRT_CONFIG_DIR "/roomba_world.yaml";
  if (value == "furnished") return ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml";
  if (value == "apartment") return ROOMBA_RRT_CONFIG_DIR "/maps/apartment.yaml";
  return value;
}

world::World loadToolWorld(const std::string& file, const std::string& pose,
                           const std::string& crop) {
  world::World world = world::readWorldFile(file).world;
  if (!crop.empty()) {
    const std::vector<double> box = parseNumbers("--crop", crop);
    if (box.size() != 4) bad("--crop", "expected X0,Y0,X1,Y1, got '" + crop + "'");
    world = world::cropped(world, {box[0], box[1], box[2], box[3]}, "--crop");
  }
  if (!pose.empty()) {
    const std::vector<double> xyt = parseNumbers("--pose", pose);
    if (xyt.size() < 2 || xyt.size() > 3)
      bad("--pose", "expected X,Y or X,Y,THETA, got '" + pose + "'");
    world.robot().initial_pose = {xyt[0], xyt[1], xyt.size() == 3 ? xyt[2] : 0.0};
  }
  try {
    world::validate(world);
  } catch (const util::InvalidInput& invalid) {
    if (invalid.field() != "initial_pose") throw invalid.in(file);
    throw util::InvalidInput("initial_pose", invalid.problem() + " (pass --pose X,Y[,THETA])",
                             file);
  }
  return world;
}

planning::Point2 parsePointFlag(const std::string& flag, const std::string& value) {
  const std::size_t comma = value.find(',');
  if (comma == std::string::npos) bad(flag, "expected X,Y, got '" + value + "'");
  return {parseDoubleFlag(flag, value.substr(0, comma)),
          parseDoubleFlag(flag, value.substr(comma + 1))};
}

planning::Problem worldProblem(ToolArguments& args, std::string* name) {
  if (!args.random_stream_given) args.options.random_stream = planning::RandomStream::kFast;
  return worldProblem(args.tool, name);
}

planning::Problem worldProblem(std::map<std::string, std::string>& tool, std::string* name) {
  const bool map = tool.count("--map") > 0;
  if (map && tool.count("--world")) bad("--map", "give --world or --map, not both");
  const std::string flag = map ? "--map" : "--world";
  const std::string file = map ? tool["--map"] : worldFile(tool["--world"]);
  if (map && !geometry::isMapYaml(file)) bad("--map", "'" + file + "' is not a map_server YAML");
  for (const char* required : {"--start", "--goal"}) {
    if (!tool.count(required)) bad(required, "required with " + flag + " (X,Y)");
  }
  // The world's own initial pose does not matter here (a map's (0, 0) may be in a wall).
  planning::Problem problem = world_planning::roomProblem(world::readWorldFile(file).world);
  problem.start = parsePointFlag("--start", tool["--start"]);
  problem.goal = parsePointFlag("--goal", tool["--goal"]);
  *name = problem.map ? "map" : "room";
  return problem;
}

int parseIntFlag(const std::string& flag, const std::string& value) {
  std::size_t used = 0;
  long long v = 0;
  try {
    v = std::stoll(value, &used);
  } catch (const std::exception&) {
    bad(flag, "expected an integer, got '" + value + "'");
  }
  if (used != value.size() || v < INT32_MIN || v > INT32_MAX) {
    bad(flag, "expected an integer, got '" + value + "'");
  }
  return static_cast<int>(v);
}

double parseDoubleFlag(const std::string& flag, const std::string& value) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(value, &used);
  } catch (const std::exception&) {
    bad(flag, "expected a number, got '" + value + "'");
  }
  if (used != value.size()) bad(flag, "expected a number, got '" + value + "'");
  if (!std::isfinite(v)) bad(flag, "expected a finite number");
  return v;
}

ToolArguments parseToolArguments(int argc, const char* const* argv,
                                 const std::set<std::string>& tool_flags,
                                 const std::set<std::string>& switches) {
  ToolArguments args;
  args.scenario_file = defaultScenarioFile();
  planning::PlannerOptions& o = args.options;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--smooth") {
      o.smooth = true;
      continue;
    }
    if (switches.count(flag)) {
      args.tool[flag] = "1";
      continue;
    }
    if (i + 1 >= argc) bad(flag, "needs a value (or is unknown)");
    const std::string value = argv[++i];
    if (flag == "--scenario") {
      args.scenario = value;
    } else if (flag == "--scenarios") {
      args.scenario_file = value;
    } else if (flag == "--algorithm") {
      o.algorithm = parseEnumFlag(flag, value, &planning::parseAlgorithm);
    } else if (flag == "--collision") {
      o.collision = parseEnumFlag(flag, value, &planning::parseCollisionCheck);
    } else if (flag == "--nearest") {
      o.nearest = parseEnumFlag(flag, value, &planning::parseNearestSearch);
    } else if (flag == "--step") {
      o.step = parseDoubleFlag(flag, value);
    } else if (flag == "--goal-bias") {
      o.goal_bias = parseDoubleFlag(flag, value);
    } else if (flag == "--goal-tolerance") {
      o.goal_tolerance = parseDoubleFlag(flag, value);
    } else if (flag == "--max-iterations") {
      o.max_iterations = parseIntFlag(flag, value);
    } else if (flag == "--random-stream") {
      o.random_stream = parseEnumFlag(flag, value, &planning::parseRandomStream);
      args.random_stream_given = true;
    } else if (flag == "--seed") {
      const double seed = parseDoubleFlag(flag, value);
      if (seed < 0 || seed > UINT32_MAX || seed != std::floor(seed)) {
        bad(flag, "must be an integer in [0, 4294967295]");
      }
      o.seed = static_cast<std::uint32_t>(seed);
    } else if (tool_flags.count(flag)) {
      args.tool[flag] = value;
    } else {
      bad(flag, "unknown flag");
    }
  }
  return args;
}

std::string commonFlagsHelp() {
  return "  --scenario NAME          a scenario of the scenario file (a, b, c, d)\n"
         "  --scenarios FILE         scenario file (default: config/rrt_scenarios.yaml)\n"
         "  --algorithm A            rrt (default), rrt_connect, rrt_star\n"
         "  --collision C            points (the lab, default) or segments\n"
         "  --nearest N              index (default) or brute_force\n"
         "  --step D                 extension step Delta (default 0.2)\n"
         "  --goal-bias P            goal bias p in [0, 1] (default 0.1)\n"
         "  --max-iterations N       iterations per run (default 1000)\n"
         "  --goal-tolerance E       epsilon (default 1e-3)\n"
         "  --seed S                 MATLAB rng(S) seed (default 42)\n"
         "  --random-stream R        matlab (MATLAB's rng(S)) or fast (xoshiro256+); default:\n"
         "                           matlab for --scenario, fast for --world and --map\n"
         "  --smooth                 shortcut-smooth each path found\n";
}

}  // namespace roomba_rrt::tools
