// libFuzzer harness: a PlanCoverage request built from the input → the coverage_planner node's own
// conversion and plan (coverage_ros.h: planCoverage), exactly as the node answers it, without a
// master. An input that starts with '{' is the request in YAML, as `rosservice call` takes it
// ({start: {x: 1, y: 1}, swath: 1e308, ...}); any other input drives a FuzzedDataProvider. The
// room is the furnished one; world "map" is the package's apartment. Checks what a client relies
// on: a refusal names a field of the request, an answer holds a finite path whose rows are marked
// inside it.
#include <fuzzer/FuzzedDataProvider.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>

#include "../../src/ros/coverage_ros.h"
#include "request_fuzzing.h"
#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/world/world_file.h"

namespace {

namespace fuzz = roomba_rrt::fuzz;

using roomba_rrt::PlanCoverage;
namespace world = roomba_rrt::world;

/// A double that is often one of the values that break arithmetic, else near the rooms' sizes.
double pickDouble(FuzzedDataProvider& in) {
  static const double kSpecial[] = {0.0,
                                    -0.0,
                                    0.01,
                                    0.17,
                                    0.33,
                                    1.0,
                                    -1.0,
                                    1e-320,
                                    1e-9,
                                    1e6,
                                    1e100,
                                    1e308,
                                    -1e308,
                                    std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity(),
                                    std::numeric_limits<double>::quiet_NaN()};
  return fuzz::pickDouble(in, kSpecial, -6.0, 8.0);
}

PlanCoverage::Request makeRequest(FuzzedDataProvider& in) {
  PlanCoverage::Request r;
  const int world = in.ConsumeIntegralInRange(0, 3);
  r.world = world == 0   ? ""
            : world == 1 ? "room"
            : world == 2 ? "map"
                         : in.ConsumeRandomLengthString(8);
  r.start.x = pickDouble(in);
  r.start.y = pickDouble(in);
  if (in.ConsumeBool()) {
    r.x_min = pickDouble(in);
    r.x_max = pickDouble(in);
    r.y_min = pickDouble(in);
    r.y_max = pickDouble(in);
  }
  r.robot_radius = in.ConsumeBool() ? pickDouble(in) : 0.0;
  r.clearance = in.ConsumeBool() ? pickDouble(in) : 0.0;
  r.swath = in.ConsumeBool() ? pickDouble(in) : 0.0;
  return r;
}

/// The request in YAML (the fields of PlanCoverage.srv); throws YAML::Exception on anything else.
PlanCoverage::Request parseRequest(const std::string& text) {
  const YAML::Node root = YAML::Load(text);
  PlanCoverage::Request r;
  if (!root.IsMap()) return r;
  for (const auto& entry : root) {
    const std::string key = entry.first.as<std::string>();
    const YAML::Node& v = entry.second;
    if (key == "world") r.world = v.as<std::string>();
    if (key == "start") {
      if (v["x"]) r.start.x = v["x"].as<double>();
      if (v["y"]) r.start.y = v["y"].as<double>();
    }
    const std::pair<const char*, double*> numbers[] = {{"x_min", &r.x_min},
                                                       {"x_max", &r.x_max},
                                                       {"y_min", &r.y_min},
                                                       {"y_max", &r.y_max},
                                                       {"robot_radius", &r.robot_radius},
                                                       {"clearance", &r.clearance},
                                                       {"swath", &r.swath}};
    for (const auto& [name, field] : numbers) {
      if (key == name) *field = v.as<double>();
    }
  }
  return r;
}

void require(bool ok, const char* what) { fuzz::require(ok, "plan_coverage_fuzzer", what); }

bool namesAField(const std::string& message) {
  for (const char* field : {"world", "start", "start.x", "start.y", "x_min..y_max", "robot_radius",
                            "clearance", "swath"}) {
    if (message.rfind(std::string(field) + ": ", 0) == 0) return true;
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const roomba_rrt::coverage_node::CoverageDefaults defaults = [] {
    roomba_rrt::coverage_node::CoverageDefaults d;
    d.room = std::make_shared<const world::World>(world::loadWorld(
        ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml", world::PoseSource::kElsewhere));
    d.map = std::make_shared<const world::World>(world::mapWorld(
        std::make_shared<const roomba_rrt::geometry::OccupancyGrid>(
            roomba_rrt::geometry::loadMap(ROOMBA_RRT_CONFIG_DIR "/maps/apartment.yaml").grid),
        0.17));
    return d;
  }();
  PlanCoverage::Request request;
  if (size > 0 && data[0] == '{') {
    try {
      request = parseRequest(std::string(reinterpret_cast<const char*>(data), size));
    } catch (const YAML::Exception&) {
      return 0;
    }
  } else {
    FuzzedDataProvider in(data, size);
    request = makeRequest(in);
  }
  world::World planned_in;
  const PlanCoverage::Response r =
      roomba_rrt::coverage_node::planCoverage(request, defaults, ros::Time(1), &planned_in);
  if (!r.success) {
    require(namesAField(r.message), "a refusal that names no field of the request");
    require(r.path.poses.empty() && r.row_starts.empty(), "a refusal with a path");
    return 0;
  }
  require(!r.path.poses.empty() && !r.row_starts.empty(), "success without rows");
  for (const auto& pose : r.path.poses) {
    const auto& p = pose.pose.position;
    const auto& q = pose.pose.orientation;
    require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(q.z) && std::isfinite(q.w),
            "a non-finite pose in the path");
  }
  double rows = 0;  // each row start's segment, which the contract says is a row
  for (std::size_t i = 0; i < r.row_starts.size(); ++i) {
    require(r.row_starts[i] + 1 < r.path.poses.size(), "a row start beyond the path");
    require(i == 0 || r.row_starts[i] > r.row_starts[i - 1], "row starts out of order");
    const auto& a = r.path.poses[r.row_starts[i]].pose.position;
    const auto& b = r.path.poses[r.row_starts[i] + 1].pose.position;
    rows += std::hypot(b.x - a.x, b.y - a.y);
  }
  require(std::abs(rows - r.row_length) <= 1e-6 * std::max(1.0, r.row_length),
          "the row starts' segments are not row_length long (a transit named a row)");
  require(std::isfinite(r.length) && std::isfinite(r.reachable_area) && r.reachable_area > 0,
          "a non-finite length or area");
  std::size_t row_points = 0;  // what rviz draws: the rows' ends
  for (const auto& m : roomba_rrt::coverage_node::toMarkers(r, &planned_in).markers) {
    if (m.ns == "rows") row_points = m.points.size();
  }
  require(row_points == 2 * r.row_starts.size(), "rviz's rows are not the answer's");
  return 0;
}
