// Conversions between the navigation interface of roomba_bt (move_base's action and topics, the
// ~plan_path service) and the ROS-free navigation core (NavBt): goal checks with messages naming
// the field, poses, plans. Pure functions, unit-tested without a master
// (test/navigation/nav_ros_test).
#pragma once

#include <cstdint>
#include <string>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/PoseStamped.h>
#include <roomba_rrt/PlanPath.h>

#include "roomba_rrt/navigation/nav_bt.h"
#include "roomba_rrt/navigation/path_planner.h"
#include "roomba_rrt/robot/robot_state.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::nav_node {

/// "" when the pose can be a goal, else the reason naming the field ("target_pose.pose.position.x:
/// not finite", "target_pose.pose.orientation: not a rotation (zero quaternion)").
std::string poseProblem(const geometry_msgs::Pose& pose);

/// The pose in the plane (x, y, yaw); `pose` must pass poseProblem().
robot::Pose2D toPose2D(const geometry_msgs::Pose& pose);

/// The planar pose as a message (z = 0, rotation about z).
geometry_msgs::PoseStamped toPoseStamped(const robot::Pose2D& pose, const std::string& frame_id,
                                         const ros::Time& stamp);

/// "" when the robot's disc (radius + clearance) fits at (x, y) in the room; else why not, as a
/// move_base client is told: "goal (7.00, 1.00) is outside the room [0, 6.4] x [0, 4.8]",
/// "goal (0.80, 0.30) is inside furniture (rectangle 0: [0, 1.6] x [0, 0.6], grown by 0.22 m for
/// the robot)", "goal ... is too close to a wall ...".
std::string goalPlaceProblem(const world::World& world, double clearance, double x, double y);

/// Where in rrt_planner roomba_bt's plans are made, and for which robot.
struct PlanTarget {
  /// "map" (the map on the planner's ~map_topic, which roomba_sim publishes) or "room" (the
  /// planner's ~world_file, which must then be roomba_bt's world).
  std::string scenario = "room";
  double robot_radius = 0;  ///< m; 0: the scenario's robot
  double clearance = 0;     ///< m
};

/// The planner's world for roomba_bt's `world`: scenario "map" when the world is a map without
/// furniture (so a planner that knows only /map, as move_base's do, plans in it), "room"
/// otherwise; the world's robot radius and `clearance`.
PlanTarget planTarget(const world::World& world, double clearance);

/// The ~plan_path request for a navigation plan in `target`: RRT-Connect, exact segment checks,
/// smoothed, with the step, iterations and tolerance of `options`
/// (navigation::navPlannerOptions() of the world).
PlanPath::Request planRequest(
    const planning::Point2& start, const planning::Point2& goal, std::uint32_t seed,
    const PlanTarget& target,
    const planning::PlannerOptions& options = navigation::defaultNavPlannerOptions());

/// The service's answer as the navigation core's plan reply.
navigation::PlanReply toPlanReply(const PlanPath::Response& response);

}  // namespace roomba_rrt::nav_node
