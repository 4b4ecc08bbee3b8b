#include "make_plan_ros.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "message_parts.h"
#include "roomba_rrt/planning/free_point_near.h"
#include "roomba_rrt/planning/grid_regions.h"
#include "roomba_rrt/planning/validate.h"
#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::planner_node {
namespace {

constexpr double kStep = 0.5;            // m
constexpr int kMaxIterations = 200'000;  // extension steps, unless ~max_iterations_cap is lower

}  // namespace

using util::show;

planning::PlannerOptions makePlanOptions(const NodeDefaults& defaults,
                                         const planning::Problem& map) {
  planning::PlannerOptions o = defaults.options;
  const bool regions =
      map.map && static_cast<std::size_t>(map.map->grid().width) * map.map->grid().height <=
                     planning::kRegionAStarMaxCells;
  o.algorithm = regions ? planning::Algorithm::kRegionAStar : planning::Algorithm::kRrtConnect;
  o.collision = planning::CollisionCheck::kSegments;
  o.step = kStep;
  o.max_iterations = std::min(kMaxIterations, defaults.max_iterations_cap);
  o.smooth = true;
  o.random_stream = planning::RandomStream::kFast;  // a map: no MATLAB stream to match
  return o;
}

MakePlanQuery resolveMakePlan(const planning::Problem& map, const robot::Pose2D& start,
                              const robot::Pose2D& goal, double tolerance,
                              const NodeDefaults& defaults) {
  MakePlanQuery query;
  query.problem = map;
  query.problem.robot_radius = mapRobotRadius(defaults);
  query.problem.clearance = defaults.clearance;
  query.problem.start = {start.x, start.y};
  query.options = makePlanOptions(defaults, map);
  query.goal_yaw = goal.theta;
  if (!(tolerance >= 0) || !std::isfinite(tolerance)) {
    query.error = "tolerance: must be a finite number >= 0, got " + show(tolerance);
    return query;
  }
  if (!std::isfinite(goal.x) || !std::isfinite(goal.y) || !std::isfinite(goal.theta)) {
    query.error = "goal: must be finite, got (" + show(goal.x) + ", " + show(goal.y) +
                  ") heading " + show(goal.theta);
    return query;
  }
  const std::optional<planning::Point2> reachable =
      planning::freePointNear(query.problem, {goal.x, goal.y}, tolerance);
  if (!reachable) {
    query.error = "goal: (" + show(goal.x) + ", " + show(goal.y) +
                  ") is in a wall of the map (within the robot's radius + clearance " +
                  show(planning::robotMargin(query.problem)) +
                  " of an occupied or unknown cell, or outside it) and no free point is within "
                  "tolerance " +
                  show(tolerance) + " m";
    return query;
  }
  query.problem.goal = *reachable;
  try {
    planning::validate(query.problem, query.options, defaults.max_iterations_cap);
  } catch (const util::InvalidInput& invalid) {
    query.error = invalid.what();
  }
  return query;
}

nav_msgs::Path toPlanMessage(const std::vector<planning::Point2>& path, double goal_yaw,
                             const std::string& frame_id, const ros::Time& stamp) {
  nav_msgs::Path plan = toPathMessage(path, frame_id, stamp);
  for (std::size_t i = 0; i + 1 < plan.poses.size(); ++i) {
    const planning::Point2 &a = path[i], &b = path[i + 1];
    plan.poses[i].pose.orientation = nodes::yawToQuaternion(std::atan2(b.y - a.y, b.x - a.x));
  }
  if (!plan.poses.empty()) plan.poses.back().pose.orientation = nodes::yawToQuaternion(goal_yaw);
  return plan;
}

}  // namespace roomba_rrt::planner_node
