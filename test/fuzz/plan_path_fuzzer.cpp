// libFuzzer harness: a PlanPath request built from the input → the rrt_planner node's own
// conversion (resolveRequest: defaults, scenarios, validation) → plan → the response, exactly as
// the node does it, without a master. An input that starts with '{' is the request in YAML, as
// `rosservice call` takes it ({start: {x: 1, y: 1}, step: 1e308, ...}): reproducers stay readable
// and the fuzzer mutates their numbers; any other input drives a FuzzedDataProvider. Iterations are
// capped at kMaxIterations inside the harness (libFuzzer's -timeout catches a plan that ignores
// them). Checks what a client relies on: a refusal names a field, an answer holds finite points.
// Scenario "map" plans on the package's apartment map; with `make_plan: true` (or a drawn bool)
// the same start and goal go through make_plan's conversion (resolveMakePlan, goal_tolerance as
// its tolerance) instead, as ~make_plan does.
#include <fuzzer/FuzzedDataProvider.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>

#include "../../src/ros/make_plan_ros.h"
#include "../../src/ros/planner_ros.h"
#include "request_fuzzing.h"
#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/planning/lab/scenarios.h"

namespace {

namespace fuzz = roomba_rrt::fuzz;

using roomba_rrt::PlanPath;
namespace planning = roomba_rrt::planning;

constexpr int kMaxIterations = 3000;

/// A double that is often one of the values that break arithmetic.
double pickDouble(FuzzedDataProvider& in) {
  static const double kSpecial[] = {0.0,
                                    -0.0,
                                    1.0,
                                    10.0,
                                    -1.0,
                                    1e-320,
                                    5e-324,
                                    1e-9,
                                    1e-6,
                                    1e6,
                                    1e100,
                                    8e307,
                                    1e308,
                                    -1e308,
                                    std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity(),
                                    std::numeric_limits<double>::quiet_NaN()};
  return fuzz::pickDouble(in, kSpecial, -2.0, 12.0);
}

std::string pickName(FuzzedDataProvider& in, std::initializer_list<const char*> names) {
  const auto index = in.ConsumeIntegralInRange<std::size_t>(0, names.size());
  if (index == names.size()) return in.ConsumeRandomLengthString(16);
  return *(names.begin() + index);
}

PlanPath::Request makeRequest(FuzzedDataProvider& in) {
  PlanPath::Request r;
  r.scenario = pickName(in, {"", "", "a", "b", "c", "d", "map"});
  r.start.x = pickDouble(in);
  r.start.y = pickDouble(in);
  r.goal.x = pickDouble(in);
  r.goal.y = pickDouble(in);
  const int obstacles = in.ConsumeIntegralInRange(0, 12);
  for (int i = 0; i < obstacles; ++i) {
    roomba_rrt::CircleObstacle o;
    o.center.x = pickDouble(in);
    o.center.y = pickDouble(in);
    o.radius = pickDouble(in);
    r.obstacles.push_back(o);
  }
  if (in.ConsumeBool()) {
    r.x_min = pickDouble(in);
    r.x_max = pickDouble(in);
    r.y_min = pickDouble(in);
    r.y_max = pickDouble(in);
  }
  r.step = in.ConsumeBool() ? pickDouble(in) : 0.0;
  r.goal_bias = in.ConsumeBool() ? pickDouble(in) : 0.0;
  r.max_iterations = in.ConsumeIntegral<std::int32_t>();
  r.goal_tolerance = in.ConsumeBool() ? pickDouble(in) : 0.0;
  r.seed = in.ConsumeIntegral<std::uint32_t>();
  r.algorithm = pickName(in, {"", "rrt", "rrt_connect", "rrt_star"});
  r.collision_check = pickName(in, {"", "points", "segments"});
  r.random_stream = pickName(in, {"", "matlab", "fast"});
  r.smooth = in.ConsumeBool();
  return r;
}

void readPoint(const YAML::Node& node, geometry_msgs::Point& point) {
  if (node["x"]) point.x = node["x"].as<double>();
  if (node["y"]) point.y = node["y"].as<double>();
}

/// The request in YAML (the fields of PlanPath.srv, and `make_plan: true`); throws
/// YAML::Exception on anything else.
PlanPath::Request parseRequest(const std::string& text, bool* make_plan) {
  const YAML::Node root = YAML::Load(text);
  PlanPath::Request r;
  if (!root.IsMap()) return r;
  for (const auto& entry : root) {
    const std::string key = entry.first.as<std::string>();
    const YAML::Node& v = entry.second;
    if (key == "make_plan") *make_plan = v.as<bool>();
    if (key == "scenario") r.scenario = v.as<std::string>();
    if (key == "start") readPoint(v, r.start);
    if (key == "goal") readPoint(v, r.goal);
    if (key == "obstacles") {
      for (const auto& item : v) {
        roomba_rrt::CircleObstacle o;
        if (item["center"]) readPoint(item["center"], o.center);
        if (item["radius"]) o.radius = item["radius"].as<double>();
        r.obstacles.push_back(o);
      }
    }
    const std::pair<const char*, double*> numbers[] = {{"x_min", &r.x_min},
                                                       {"x_max", &r.x_max},
                                                       {"y_min", &r.y_min},
                                                       {"y_max", &r.y_max},
                                                       {"step", &r.step},
                                                       {"goal_bias", &r.goal_bias},
                                                       {"goal_tolerance", &r.goal_tolerance}};
    for (const auto& [name, field] : numbers) {
      if (key == name) *field = v.as<double>();
    }
    if (key == "max_iterations") r.max_iterations = v.as<std::int32_t>();
    if (key == "seed") r.seed = v.as<std::uint32_t>();
    if (key == "algorithm") r.algorithm = v.as<std::string>();
    if (key == "collision_check") r.collision_check = v.as<std::string>();
    if (key == "random_stream") r.random_stream = v.as<std::string>();
    if (key == "smooth") r.smooth = v.as<bool>();
  }
  return r;
}

void require(bool ok, const char* what) { fuzz::require(ok, "plan_path_fuzzer", what); }

}  // namespace

/// make_plan's conversion of the request's start, goal and goal_tolerance (as its tolerance),
/// then the plan and the nav_msgs/Path it answers.
int makePlan(const PlanPath::Request& r, const planning::Problem& map,
             const roomba_rrt::planner_node::NodeDefaults& defaults) {
  namespace node = roomba_rrt::planner_node;
  const node::MakePlanQuery query =
      node::resolveMakePlan(map, {r.start.x, r.start.y, r.goal_bias}, {r.goal.x, r.goal.y, r.step},
                            r.goal_tolerance, defaults);
  if (!query.error.empty()) return 0;  // no plan, the reason logged
  planning::PlannerOptions options = query.options;
  options.max_iterations = std::min(options.max_iterations, kMaxIterations);
  const planning::PlanResult result = planning::plan(query.problem, options);
  const nav_msgs::Path plan = node::toPlanMessage(result.path, query.goal_yaw, "map", ros::Time(1));
  for (const auto& pose : plan.poses) {
    const auto& p = pose.pose.position;
    const auto& q = pose.pose.orientation;
    require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(q.z) && std::isfinite(q.w),
            "a non-finite pose in make_plan's plan");
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::map<std::string, planning::Problem> scenarios =
      planning::loadScenarios(ROOMBA_RRT_CONFIG_DIR "/rrt_scenarios.yaml");
  static const planning::Problem map =
      planning::mapProblem(std::make_shared<const roomba_rrt::geometry::OccupancyGrid>(
          roomba_rrt::geometry::loadMap(ROOMBA_RRT_CONFIG_DIR "/maps/apartment.yaml").grid));
  PlanPath::Request request;
  bool make_plan = false;
  if (size > 0 && data[0] == '{') {
    try {
      request = parseRequest(std::string(reinterpret_cast<const char*>(data), size), &make_plan);
    } catch (const YAML::Exception&) {
      return 0;
    }
  } else {
    FuzzedDataProvider in(data, size);
    request = makeRequest(in);
    make_plan = in.ConsumeBool();
  }
  // The harness's cap: a plan of at most kMaxIterations (the node's cap is 5,000,000).
  if (request.max_iterations > kMaxIterations) request.max_iterations = kMaxIterations;
  roomba_rrt::planner_node::NodeDefaults defaults;
  defaults.max_iterations_cap = kMaxIterations;
  if (make_plan && request.scenario == "map") return makePlan(request, map, defaults);
  const auto resolved =
      roomba_rrt::planner_node::resolveRequest(request, defaults, scenarios, &map);
  if (!resolved.error.empty()) return 0;  // refused, naming the field
  const planning::PlanResult result = planning::plan(resolved.problem, resolved.options);
  PlanPath::Response response;
  roomba_rrt::planner_node::fillResponse(result, "map", ros::Time(1), &response);
  require(!result.success || !result.path.empty(), "success with an empty path");
  for (const auto& pose : response.path.poses) {
    require(std::isfinite(pose.pose.position.x) && std::isfinite(pose.pose.position.y),
            "a non-finite point in the returned path");
  }
  return 0;
}
