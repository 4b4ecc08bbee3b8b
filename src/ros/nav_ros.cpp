#include "nav_ros.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "message_parts.h"
#include "roomba_rrt/geometry/occupancy_grid.h"
#include "roomba_rrt/navigation/nav_bt.h"

namespace roomba_rrt::nav_node {
namespace {

std::string format(const char* fmt, double a, double b, double c = 0, double d = 0, double e = 0,
                   double f = 0) {
  char text[256];
  std::snprintf(text, sizeof text, fmt, a, b, c, d, e, f);
  return text;
}

}  // namespace

std::string poseProblem(const geometry_msgs::Pose& pose) {
  const std::pair<const char*, double> fields[] = {
      {"position.x", pose.position.x},       {"position.y", pose.position.y},
      {"position.z", pose.position.z},       {"orientation.x", pose.orientation.x},
      {"orientation.y", pose.orientation.y}, {"orientation.z", pose.orientation.z},
      {"orientation.w", pose.orientation.w}};
  for (const auto& [name, value] : fields) {
    if (!std::isfinite(value)) return std::string("target_pose.pose.") + name + ": not finite";
  }
  const auto& q = pose.orientation;
  const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (norm < 1e-6) return "target_pose.pose.orientation: not a rotation (zero quaternion)";
  return "";
}

robot::Pose2D toPose2D(const geometry_msgs::Pose& pose) {
  return {pose.position.x, pose.position.y, nodes::quaternionToYaw(pose.orientation)};
}

geometry_msgs::PoseStamped toPoseStamped(const robot::Pose2D& pose, const std::string& frame_id,
                                         const ros::Time& stamp) {
  geometry_msgs::PoseStamped msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp = stamp;
  msg.pose.position.x = pose.x;
  msg.pose.position.y = pose.y;
  msg.pose.orientation = nodes::yawToQuaternion(pose.theta);
  return msg;
}

std::string goalPlaceProblem(const world::World& world, double clearance, double x, double y) {
  const double margin = world.robot().radius + clearance;
  const double x0 = world.room.origin.x, y0 = world.room.origin.y;
  const double x1 = x0 + world.room.width, y1 = y0 + world.room.height;
  if (x < x0 || x > x1 || y < y0 || y > y1) {
    return format("goal (%.2f, %.2f) is outside the room [%g, %g] x ", x, y, x0, x1) +
           format("[%g, %g]", y0, y1);
  }
  for (std::size_t i = 0; i < world.room.rectangles.size(); ++i) {
    const auto& r = world.room.rectangles[i];
    const double dx = std::max({r.min_x - x, 0.0, x - r.max_x});
    const double dy = std::max({r.min_y - y, 0.0, y - r.max_y});
    if (std::hypot(dx, dy) < margin) {
      return format("goal (%.2f, %.2f) is inside furniture (rectangle %.0f: [%g, %g] x ", x, y,
                    static_cast<double>(i), r.min_x, r.max_x) +
             format("[%g, %g], grown by %.2f m for the robot)", r.min_y, r.max_y, margin);
    }
  }
  for (std::size_t i = 0; i < world.room.circles.size(); ++i) {
    const auto& c = world.room.circles[i];
    if (std::hypot(x - c.center.x, y - c.center.y) < c.radius + margin) {
      return format("goal (%.2f, %.2f) is inside furniture (circle %.0f at (%g, %g)", x, y,
                    static_cast<double>(i), c.center.x, c.center.y) +
             format(" of radius %g, grown by %.2f m for the robot)", c.radius, margin);
    }
  }
  if (x < x0 + margin || x > x1 - margin || y < y0 + margin || y > y1 - margin) {
    return format("goal (%.2f, %.2f) is too close to a wall (the robot needs %.2f m)", x, y,
                  margin);
  }
  if (world.room.map && geometry::blockedWithin(*world.room.map, {x, y}, margin)) {
    return format("goal (%.2f, %.2f) is in or too close to a wall of the map (an occupied or ", x,
                  y) +
           format("unknown cell; the robot needs %.2f m)", margin, 0);
  }
  return "";
}

PlanTarget planTarget(const world::World& world, double clearance) {
  PlanTarget target;
  const bool map_alone =
      world.room.map && world.room.circles.empty() && world.room.rectangles.empty();
  target.scenario = map_alone ? "map" : "room";
  target.robot_radius = world.robot().radius;
  target.clearance = clearance;
  return target;
}

PlanPath::Request planRequest(const planning::Point2& start, const planning::Point2& goal,
                              std::uint32_t seed, const PlanTarget& target,
                              const planning::PlannerOptions& options) {
  // PlanPath reads exactly (0, 0) as "not given" (its zero-means-default rule), and a map's
  // robot starts there: such a point is sent a nanometre away.
  const auto given = [](const planning::Point2& p) {
    return p.x == 0 && p.y == 0 ? planning::Point2{1e-9, 0} : p;
  };
  PlanPath::Request request;
  request.scenario = target.scenario;
  request.start.x = given(start).x;
  request.start.y = given(start).y;
  request.goal.x = given(goal).x;
  request.goal.y = given(goal).y;
  request.step = options.step;
  request.max_iterations = options.max_iterations;
  request.goal_tolerance = options.goal_tolerance;
  request.seed = seed == 0 ? 1 : seed;  // 0 would mean the node's ~seed
  request.algorithm = "rrt_connect";
  request.collision_check = "segments";
  request.smooth = options.smooth;
  request.robot_radius = target.robot_radius;
  request.clearance = target.clearance;
  return request;
}

navigation::PlanReply toPlanReply(const PlanPath::Response& response) {
  navigation::PlanReply reply;
  reply.success = response.success;
  reply.message = response.message;
  reply.planning_ms = response.planning_time * 1e3;
  if (!response.success) return reply;
  reply.path.reserve(response.path.poses.size());
  for (const auto& pose : response.path.poses) {
    reply.path.push_back({pose.pose.position.x, pose.pose.position.y});
  }
  return reply;
}

}  // namespace roomba_rrt::nav_node
