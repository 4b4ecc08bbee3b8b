// make_plan: move_base's global-planner service (nav_msgs/GetPlan) answered on the planner's map. A
// ROS tool that asks move_base, navfn or global_planner for a plan can ask rrt_planner the same
// way. ROS messages in and out; the planning itself is the library's.
#pragma once

#include <string>
#include <vector>

#include <nav_msgs/Path.h>
#include <ros/time.h>

#include "planner_ros.h"
#include "roomba_rrt/robot/robot_state.h"

namespace roomba_rrt::planner_node {

/// How make_plan plans on `map` (the node's ~max_planning_time applies; the rest is fixed so a
/// map plans well without a request saying how): region_astar, a path as short as navfn's and
/// global_planner's in a fraction of their time (doc/planning.md), on maps of up to
/// planning::kRegionAStarMaxCells cells; on larger ones RRT-Connect (~seed, ~goal_tolerance,
/// ~max_iterations_cap apply), every edge checked whole, steps of 0.5 m, up to 200 000
/// iterations, the path shortcut-smoothed, drawn from
/// the fast stream.
planning::PlannerOptions makePlanOptions(const NodeDefaults& defaults,
                                         const planning::Problem& map);

/// A make_plan request as the library's input, or why it cannot be planned.
struct MakePlanQuery {
  planning::Problem problem;
  planning::PlannerOptions options;
  double goal_yaw = 0;  ///< the goal's heading: the plan's last pose faces it
  std::string error;    ///< "" or the reason, naming the field ("goal: ... in a wall ...")
};

/// Start and goal (already in the map's frame) on `map` for the robot ~robot_radius (the
/// Roomba's 0.17 m when 0) + ~clearance. `tolerance` as move_base: a goal in a wall is moved to
/// the nearest free point within tolerance in x and y (planning::freePointNear); none: an error.
MakePlanQuery resolveMakePlan(const planning::Problem& map, const robot::Pose2D& start,
                              const robot::Pose2D& goal, double tolerance,
                              const NodeDefaults& defaults);

/// The plan as move_base's global planners return it: every point of the path in `frame_id`,
/// each pose facing the next point, the last one with the goal's heading; empty when `path` is.
nav_msgs::Path toPlanMessage(const std::vector<planning::Point2>& path, double goal_yaw,
                             const std::string& frame_id, const ros::Time& stamp);

}  // namespace roomba_rrt::planner_node
