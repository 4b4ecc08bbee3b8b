// libFuzzer harness: a nav_msgs/OccupancyGrid as it arrives on /map → the nodes' own conversion
// (map_messages.h: fromMapMessage) → if accepted, what rrt_planner (planning::mapProblem) and
// coverage_planner (world::mapWorld) build from it. An input that starts with '{' is the message
// in YAML, as `rostopic pub` takes it ({info: {resolution: 1e-30, width: 3, height: 2, origin:
// {orientation: {w: 1}}}, data: [0, 100, -1, 0, 0, 0]}); any other input drives a
// FuzzedDataProvider (sizes, resolution, origin and quaternion, often NaN, ±inf, denormals,
// 3e38; data of width × height cells or not). Checks what a node relies on: a refusal names a
// field of the message and leaves the grid untouched; an accepted map lies within the ranges a
// map file is held to (map_file.h) and has width × height cells.
#include <fuzzer/FuzzedDataProvider.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>

#include "../../src/ros/map_messages.h"
#include "request_fuzzing.h"
#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/planning/problem.h"
#include "roomba_rrt/world/world.h"

namespace {

namespace fuzz = roomba_rrt::fuzz;
using roomba_rrt::geometry::MapLimits;

void require(bool ok, const char* what) { fuzz::require(ok, "map_message_fuzzer", what); }

double pickDouble(FuzzedDataProvider& in) {
  static const double kSpecial[] = {0.0,
                                    -0.0,
                                    0.05,
                                    1.0,
                                    -1.0,
                                    1e-30,
                                    1.4e-45,
                                    1e-4,
                                    100.0,
                                    3e38,
                                    1e6,
                                    -1e6,
                                    1e308,
                                    1e-320,
                                    std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity(),
                                    std::numeric_limits<double>::quiet_NaN()};
  return fuzz::pickDouble(in, kSpecial, -20.0, 20.0);
}

nav_msgs::OccupancyGrid makeMessage(FuzzedDataProvider& in) {
  nav_msgs::OccupancyGrid m;
  const bool small = in.ConsumeBool();
  m.info.width =
      small ? in.ConsumeIntegralInRange<std::uint32_t>(0, 64) : in.ConsumeIntegral<std::uint32_t>();
  m.info.height =
      small ? in.ConsumeIntegralInRange<std::uint32_t>(0, 64) : in.ConsumeIntegral<std::uint32_t>();
  m.info.resolution = static_cast<float>(pickDouble(in));
  m.info.origin.position.x = pickDouble(in);
  m.info.origin.position.y = pickDouble(in);
  auto& q = m.info.origin.orientation;
  if (in.ConsumeBool()) {
    q.w = 1;
  } else {
    q.x = pickDouble(in);
    q.y = pickDouble(in);
    q.z = pickDouble(in);
    q.w = pickDouble(in);
  }
  const std::size_t cells = static_cast<std::size_t>(m.info.width) * m.info.height;
  const std::size_t size = small && in.ConsumeBool() ? cells : in.ConsumeIntegralInRange(0, 4096);
  m.data.resize(size);
  for (auto& cell : m.data) cell = in.ConsumeIntegral<std::int8_t>();
  return m;
}

/// The message in YAML; throws YAML::Exception on anything else.
nav_msgs::OccupancyGrid parseMessage(const std::string& text) {
  const YAML::Node root = YAML::Load(text);
  nav_msgs::OccupancyGrid m;
  m.info.origin.orientation.w = 1;
  const YAML::Node info = root["info"];
  if (info["resolution"]) m.info.resolution = info["resolution"].as<float>();
  if (info["width"]) m.info.width = info["width"].as<std::uint32_t>();
  if (info["height"]) m.info.height = info["height"].as<std::uint32_t>();
  const YAML::Node origin = info["origin"];
  if (origin["position"]["x"]) m.info.origin.position.x = origin["position"]["x"].as<double>();
  if (origin["position"]["y"]) m.info.origin.position.y = origin["position"]["y"].as<double>();
  const YAML::Node q = origin["orientation"];
  if (q) m.info.origin.orientation.w = 0;
  if (q["x"]) m.info.origin.orientation.x = q["x"].as<double>();
  if (q["y"]) m.info.origin.orientation.y = q["y"].as<double>();
  if (q["z"]) m.info.origin.orientation.z = q["z"].as<double>();
  if (q["w"]) m.info.origin.orientation.w = q["w"].as<double>();
  const YAML::Node data = root["data"];
  if (data.IsSequence() && data.size() <= 1u << 16) {
    for (const auto& cell : data) m.data.push_back(static_cast<std::int8_t>(cell.as<int>()));
  }
  return m;
}

bool namesAField(const std::string& message) {
  for (const char* field :
       {"info.resolution: ", "info.origin.position.x: ", "info.origin.position.y: ",
        "info.origin.orientation: ", "info.width, info.height: ", "data: "}) {
    if (message.rfind(field, 0) == 0) return true;
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  nav_msgs::OccupancyGrid message;
  if (size > 0 && data[0] == '{') {
    try {
      message = parseMessage(std::string(reinterpret_cast<const char*>(data), size));
    } catch (const YAML::Exception&) {
      return 0;
    }
  } else {
    FuzzedDataProvider in(data, size);
    message = makeMessage(in);
  }
  auto grid = std::make_shared<roomba_rrt::geometry::OccupancyGrid>();
  const std::string error = roomba_rrt::nodes::fromMapMessage(message, grid.get());
  if (!error.empty()) {
    require(namesAField(error), "a refusal that names no field of the message");
    require(grid->cells.empty() && grid->width == 0, "a refused map was written");
    return 0;
  }
  require(grid->resolution >= MapLimits::kMinResolution &&
              grid->resolution <= MapLimits::kMaxResolution,
          "a resolution a map file may not have");
  require(std::abs(grid->origin.x) <= MapLimits::kMaxCoordinate &&
              std::abs(grid->origin.y) <= MapLimits::kMaxCoordinate,
          "an origin a map file may not have");
  require(grid->width > 0 && grid->height > 0 &&
              grid->cells.size() == static_cast<std::size_t>(grid->width) * grid->height,
          "cells = width x height");
  const roomba_rrt::planning::Problem problem = roomba_rrt::planning::mapProblem(grid);
  require(problem.map != nullptr, "rrt_planner's problem has the map");
  const roomba_rrt::world::World world = roomba_rrt::world::mapWorld(grid, 0.17);
  require(std::isfinite(world.room.width) && std::isfinite(world.room.height),
          "a finite map world");
  return 0;
}
