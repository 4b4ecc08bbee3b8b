// roomba_bt's navigation conversions without a master (src/ros/nav_ros.h): goals refused with
// the field or the furniture named, poses, plan requests and replies.
#include <gtest/gtest.h>

#include <cmath>

#include "../../src/ros/nav_ros.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::nav_node {
namespace {

world::World furnished() {
  return world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml");
}

geometry_msgs::Pose poseAt(double x, double y, double yaw) {
  return toPoseStamped({x, y, yaw}, "map", ros::Time()).pose;
}

TEST(NavRos, nan_anywhere_in_the_goal_pose_is_named) {
  geometry_msgs::Pose pose = poseAt(1, 2, 0);
  EXPECT_EQ(poseProblem(pose), "");
  pose.position.y = std::nan("");
  EXPECT_EQ(poseProblem(pose), "target_pose.pose.position.y: not finite");
  pose = poseAt(1, 2, 0);
  pose.orientation.w = INFINITY;
  EXPECT_EQ(poseProblem(pose), "target_pose.pose.orientation.w: not finite");
}

TEST(NavRos, an_all_zero_orientation_is_refused) {
  geometry_msgs::Pose pose = poseAt(1, 2, 0);
  pose.orientation.w = 0;
  EXPECT_NE(poseProblem(pose).find("orientation: not a rotation"), std::string::npos);
}

TEST(NavRos, yaw_round_trips_and_unnormalised_quaternions_are_accepted) {
  for (double yaw : {0.0, 1.0, -2.5, 3.1}) {
    EXPECT_NEAR(toPose2D(poseAt(1, 2, yaw)).theta, yaw, 1e-12);
  }
  geometry_msgs::Pose pose = poseAt(1, 2, M_PI_2);
  pose.orientation.z *= 3;
  pose.orientation.w *= 3;
  EXPECT_NEAR(toPose2D(pose).theta, M_PI_2, 1e-12);
}

TEST(NavRos, a_huge_but_finite_orientation_is_a_heading_not_nan) {
  geometry_msgs::Pose pose = poseAt(1, 2, 0);
  pose.orientation.x = pose.orientation.y = pose.orientation.z = pose.orientation.w = 1e300;
  EXPECT_EQ(poseProblem(pose), "");
  EXPECT_NEAR(toPose2D(pose).theta, M_PI_2, 1e-12);  // (0.5, 0.5, 0.5, 0.5): a quarter turn
  pose = poseAt(1, 2, -2.0);
  pose.orientation.z *= 1e306;
  pose.orientation.w *= 1e306;
  EXPECT_NEAR(toPose2D(pose).theta, -2.0, 1e-12);
}

TEST(NavRos, goal_in_the_sofa_names_the_furniture) {
  const std::string why = goalPlaceProblem(furnished(), 0.05, 0.8, 0.3);
  EXPECT_NE(why.find("inside furniture (rectangle 0"), std::string::npos) << why;
}

TEST(NavRos, goal_near_the_table_names_the_circle) {
  const std::string why = goalPlaceProblem(furnished(), 0.05, 1.3, 3.9);
  EXPECT_NE(why.find("inside furniture (circle 0"), std::string::npos) << why;
}

TEST(NavRos, goal_outside_the_room_or_against_a_wall_is_refused) {
  EXPECT_NE(goalPlaceProblem(furnished(), 0.05, 7.0, 1.0).find("outside the room"),
            std::string::npos);
  EXPECT_NE(goalPlaceProblem(furnished(), 0.05, 3.0, 0.1).find("too close to a wall"),
            std::string::npos);
}

TEST(NavRos, goal_behind_the_bench_fits) {
  EXPECT_EQ(goalPlaceProblem(furnished(), 0.05, 3.0, 4.55), "");
}

TEST(NavRos, plan_request_asks_the_room_scenario_for_a_smoothed_rrt_connect_path) {
  const PlanPath::Request request = planRequest({1, 2}, {3, 4}, 7, {"room", 0.17, 0.05});
  EXPECT_EQ(request.scenario, "room");
  EXPECT_EQ(request.robot_radius, 0.17);
  EXPECT_EQ(request.clearance, 0.05);
  EXPECT_EQ(request.algorithm, "rrt_connect");
  EXPECT_EQ(request.collision_check, "segments");
  EXPECT_TRUE(request.smooth);
  EXPECT_EQ(request.start.x, 1);
  EXPECT_EQ(request.goal.y, 4);
  EXPECT_EQ(request.seed, 7u);
  EXPECT_EQ(planRequest({1, 2}, {3, 4}, 0, {}).seed, 1u);  // 0 would be the node's ~seed
}

TEST(NavRos, a_map_world_is_planned_in_the_planners_map_and_a_room_in_its_room) {
  // A planner that knows only /map (as move_base's do) has no room of roomba_bt's map world.
  world::World apartment =
      world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/maps/apartment.yaml", world::PoseSource::kElsewhere);
  apartment.robot().radius = 0.2;
  const PlanTarget in_map = planTarget(apartment, 0.03);
  EXPECT_EQ(in_map.scenario, "map");
  EXPECT_EQ(in_map.robot_radius, 0.2);  // the world's robot, not the planner's
  EXPECT_EQ(in_map.clearance, 0.03);
  EXPECT_EQ(planRequest({1, 2}, {3, 4}, 7, in_map).scenario, "map");
  // Furniture is only in the world file: the planner's room must have it.
  apartment.room.rectangles.push_back({0, 0, 1, 1});
  EXPECT_EQ(planTarget(apartment, 0.03).scenario, "room");
  EXPECT_EQ(planTarget(world::World{}, 0.03).scenario, "room");
}

TEST(NavRos, plan_reply_carries_the_path_or_the_message) {
  PlanPath::Response response;
  response.success = false;
  response.message = "goal: inside obstacle 0";
  navigation::PlanReply reply = toPlanReply(response);
  EXPECT_FALSE(reply.success);
  EXPECT_EQ(reply.message, "goal: inside obstacle 0");
  response.success = true;
  response.planning_time = 0.002;
  response.path.poses.resize(2);
  response.path.poses[1].pose.position.x = 5;
  reply = toPlanReply(response);
  ASSERT_EQ(reply.path.size(), 2u);
  EXPECT_EQ(reply.path[1].x, 5);
  EXPECT_DOUBLE_EQ(reply.planning_ms, 2.0);
}

}  // namespace
}  // namespace roomba_rrt::nav_node
