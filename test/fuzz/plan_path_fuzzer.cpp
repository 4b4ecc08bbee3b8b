// libFuzzer harness: a PlanPath request built from the input → the rrt_planner node's own
// conversion (resolveRequest: defaults, scenarios, validation) → plan → the response, exactly as
// the node does it, without a master. Iterations are capped at kMaxIterations inside the harness
// (libFuzzer's -timeout catches a plan that ignores them). Checks what a client relies on: a
// refusal names a field, an answer holds finite points.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <string>

#include "../../src/nodes/planner_ros.h"

namespace {

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
  switch (in.ConsumeIntegralInRange(0, 3)) {
    case 0:
      return in.PickValueInArray(kSpecial);
    case 1:
      return in.ConsumeFloatingPoint<double>();
    default:
      return in.ConsumeFloatingPointInRange(-2.0, 12.0);
  }
}

std::string pickName(FuzzedDataProvider& in, std::initializer_list<const char*> names) {
  const auto index = in.ConsumeIntegralInRange<std::size_t>(0, names.size());
  if (index == names.size()) return in.ConsumeRandomLengthString(16);
  return *(names.begin() + index);
}

PlanPath::Request makeRequest(FuzzedDataProvider& in) {
  PlanPath::Request r;
  r.scenario = pickName(in, {"", "", "a", "b", "c", "d"});
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
  r.smooth = in.ConsumeBool();
  return r;
}

void require(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "plan_path_fuzzer: %s\n", what);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::map<std::string, planning::Problem> scenarios =
      planning::loadScenarios(planning::defaultScenarioFile());
  FuzzedDataProvider in(data, size);
  PlanPath::Request request = makeRequest(in);
  // The harness's cap: a plan of at most kMaxIterations (the node's cap is 5,000,000).
  if (request.max_iterations > kMaxIterations) request.max_iterations = kMaxIterations;
  roomba_rrt::planner_node::NodeDefaults defaults;
  defaults.max_iterations_cap = kMaxIterations;
  const auto resolved = roomba_rrt::planner_node::resolveRequest(request, defaults, scenarios);
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
