#include "coverage_ros.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include <roomba_rrt/util/invalid_input.h>
#include <roomba_rrt/util/require.h>

#include "message_parts.h"

namespace roomba_rrt::coverage_node {
namespace {

/// The world the request names, cut to its region and with its robot, or util::InvalidInput.
world::World requestedWorld(const PlanCoverage::Request& r, const CoverageDefaults& d) {
  std::shared_ptr<const world::World> source;
  if (r.world.empty() || r.world == "room") {
    source = d.room;
  } else if (r.world == "map") {
    source = d.map;
    if (!source) throw util::InvalidInput("world", "no map has arrived on ~map_topic yet");
  } else {
    throw util::InvalidInput("world", "must be \"room\", \"map\" or \"\", got \"" + r.world + "\"");
  }
  world::World w = *source;
  if (r.robot_radius != 0) {
    util::requireInRange("robot_radius", r.robot_radius, 1e-3, world::WorldLimits::kMaxRobotRadius,
                         "m");
    w.robot().radius = r.robot_radius;
  }
  if (r.x_min != 0 || r.x_max != 0 || r.y_min != 0 || r.y_max != 0) {
    w = world::cropped(std::move(w), {r.x_min, r.y_min, r.x_max, r.y_max}, "x_min..y_max");
  }
  try {
    world::validateRoom(w, w.robot().radius);  // the room it describes, not the robots' rules
  } catch (const util::InvalidInput& e) {      // ~world_file's world was valid: the request's fault
    const std::string field = r.robot_radius != 0 ? "robot_radius" : "x_min..y_max";
    throw util::InvalidInput(field, "the world is not valid with it: " + std::string(e.what()));
  }
  return w;
}

/// The planner's options: the world's cleaning options with the request's clearance and swath.
coverage::CoverageOptions requestedOptions(const PlanCoverage::Request& r,
                                           const CoverageDefaults& d, const world::World& w) {
  coverage::CoverageOptions o = coverage::cleaningOptions(w);
  if (w.robot().radius < o.resolution) {  // the lattice the world's floor is sampled on
    throw util::InvalidInput("robot_radius", "must be at least the world's lattice edge (" +
                                                 util::show(o.resolution) + " m), got " +
                                                 util::show(w.robot().radius));
  }
  o.clearance = r.clearance != 0 ? r.clearance : d.clearance;
  if (r.clearance != 0) util::requireInRange("clearance", r.clearance, 0.0, w.robot().radius, "m");
  if (r.swath != 0) o.swath = r.swath;  // else the robot's diameter less the overlap
  return o;
}

/// The room's walls and its furniture, flat below the plan.
void addWorld(const world::World& w, const std::string& frame, const ros::Time& stamp,
              visualization_msgs::MarkerArray& array) {
  using visualization_msgs::Marker;
  const std_msgs::ColorRGBA grey = nodes::color(0.35f, 0.35f, 0.35f);
  array.markers.push_back(
      nodes::outline({w.room.origin.x, w.room.origin.y, w.room.origin.x + w.room.width,
                      w.room.origin.y + w.room.height},
                     nodes::makeMarker(frame, stamp, "room", 0, Marker::LINE_STRIP, grey), 0.03));
  int id = 0;
  for (const geometry::Circle& c : w.room.circles) {
    array.markers.push_back(nodes::flatFurniture(
        c, nodes::makeMarker(frame, stamp, "furniture", id++, Marker::CYLINDER, grey)));
  }
  for (const geometry::Rectangle& r : w.room.rectangles) {
    array.markers.push_back(nodes::flatFurniture(
        r, nodes::makeMarker(frame, stamp, "furniture", id++, Marker::CUBE, grey)));
  }
}

}  // namespace

nav_msgs::Path toPathMessage(const coverage::CoveragePlan& plan, const std::string& frame_id,
                             const ros::Time& stamp, std::vector<std::uint32_t>* row_starts) {
  std::vector<coverage::Point2> points;
  for (const coverage::Leg& leg : plan.legs) {
    for (std::size_t k = 0; k < leg.points.size(); ++k) {
      const coverage::Point2& p = leg.points[k];
      if (!points.empty() && points.back().x == p.x && points.back().y == p.y) continue;
      points.push_back(p);
      // Each segment a row adds is marked at its first pose; a row of no length adds none, so
      // it marks nothing (marking the pose before it would name the transit after it a row).
      if (k > 0 && leg.kind == coverage::Leg::Kind::kRow && row_starts) {
        row_starts->push_back(static_cast<std::uint32_t>(points.size() - 2));
      }
    }
  }
  nav_msgs::Path path;
  path.header.frame_id = frame_id;
  path.header.stamp = stamp;
  double yaw = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (k + 1 < points.size()) {  // the last pose keeps the heading it arrives with
      yaw = std::atan2(points[k + 1].y - points[k].y, points[k + 1].x - points[k].x);
    }
    geometry_msgs::PoseStamped pose;
    pose.header = path.header;
    pose.pose.position.x = points[k].x;
    pose.pose.position.y = points[k].y;
    pose.pose.orientation = nodes::yawToQuaternion(yaw);
    path.poses.push_back(pose);
  }
  return path;
}

visualization_msgs::MarkerArray toMarkers(const PlanCoverage::Response& answer,
                                          const world::World* world) {
  using visualization_msgs::Marker;
  const std::string& frame = answer.path.header.frame_id;
  const ros::Time& stamp = answer.path.header.stamp;
  visualization_msgs::MarkerArray array;
  array.markers.push_back(nodes::deleteAllMarker(frame, stamp));
  const auto& poses = answer.path.poses;
  if (poses.empty()) return array;
  Marker rows = nodes::makeMarker(frame, stamp, "rows", 0, Marker::LINE_LIST,
                                  nodes::color(0.0f, 0.6f, 0.25f));
  rows.scale.x = 0.04;
  Marker transits = nodes::makeMarker(frame, stamp, "transits", 0, Marker::LINE_LIST,
                                      nodes::color(1.0f, 0.55f, 0.0f, 0.9f));
  transits.scale.x = 0.015;
  Marker starts = nodes::makeMarker(frame, stamp, "row_starts", 0, Marker::POINTS,
                                    nodes::color(0.0f, 0.35f, 0.15f));
  starts.scale.x = starts.scale.y = 0.07;
  std::vector<bool> row(poses.size(), false);  // row[k]: poses k and k + 1 are a row's ends
  for (const std::uint32_t k : answer.row_starts) {
    if (k + 1 < poses.size()) row[k] = true;
  }
  for (std::size_t k = 0; k + 1 < poses.size(); ++k) {
    Marker& line = row[k] ? rows : transits;
    line.points.push_back(poses[k].pose.position);
    line.points.push_back(poses[k + 1].pose.position);
    if (row[k]) starts.points.push_back(poses[k].pose.position);
  }
  Marker start =
      nodes::makeMarker(frame, stamp, "start", 0, Marker::SPHERE, nodes::color(0.1f, 0.7f, 0.1f));
  start.pose.position = poses.front().pose.position;
  start.scale.x = start.scale.y = start.scale.z = 0.15;
  array.markers.push_back(start);
  for (Marker* m : {&rows, &transits, &starts}) {
    if (!m->points.empty()) array.markers.push_back(std::move(*m));
  }
  if (world != nullptr) addWorld(*world, frame, stamp, array);
  return array;
}

PlanCoverage::Response planCoverage(const PlanCoverage::Request& request,
                                    const CoverageDefaults& defaults, const ros::Time& stamp,
                                    world::World* planned_in) {
  PlanCoverage::Response response;
  response.path.header.frame_id = defaults.frame_id;
  response.path.header.stamp = stamp;
  try {
    util::requireFinite("start.x", request.start.x);
    util::requireFinite("start.y", request.start.y);
    util::requireFinite("start.z", request.start.z);  // unused, but a NaN is a client's bug
    const world::World world = requestedWorld(request, defaults);
    if (planned_in != nullptr) *planned_in = world;
    const coverage::CoverageOptions options = requestedOptions(request, defaults, world);
    // Checked before the planner samples the world (seconds on a whole building's map).
    const coverage::Point2 start{request.start.x, request.start.y};
    const double x1 = world.room.origin.x + world.room.width,
                 y1 = world.room.origin.y + world.room.height;
    if (!(start.x >= world.room.origin.x && start.x <= x1 && start.y >= world.room.origin.y &&
          start.y <= y1)) {
      throw util::InvalidInput("start", "must lie in the world (" +
                                            util::show(world.room.origin.x) + ", " +
                                            util::show(world.room.origin.y) + ") to (" +
                                            util::show(x1) + ", " + util::show(y1) + ")");
    }
    const auto started = std::chrono::steady_clock::now();
    const coverage::CoveragePlanner planner(world, options);  // InvalidInput naming an option
    const coverage::CoveragePlan plan = planner.plan(start);
    response.planning_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    response.floor_area = plan.floor_area;
    response.reachable_area = plan.reachable_area;
    response.unreachable_area = plan.unreachable_area;
    response.swept_area = plan.swept_area;
    response.cells = plan.cells;
    if (plan.reachable_area == 0) {
      throw util::InvalidInput("start",
                               "the robot's disc does not fit there (a wall, furniture "
                               "or a blocked cell)");
    }
    if (plan.legs.empty()) {
      throw util::InvalidInput("start",
                               "the robot cannot drive from there to any point that "
                               "keeps the clearance (" +
                                   util::show(options.clearance) + " m)");
    }
    response.path = toPathMessage(plan, defaults.frame_id, stamp, &response.row_starts);
    response.length = plan.length();
    response.row_length = plan.rowLength();
    response.success = true;
  } catch (const util::InvalidInput& e) {
    response.success = false;
    response.message = e.what();
  }
  return response;
}

}  // namespace roomba_rrt::coverage_node
