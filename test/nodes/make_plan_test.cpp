// rrt_planner's ~make_plan (nav_msgs/GetPlan) on the map of /map, as a move_base user sees it
// (issue 45): asked before the first map has arrived it waits for it (up to 5 s) instead of
// answering "no map yet"; its plan has a pose every map cell, as navfn's, so that a local planner
// finds poses inside its window.
#include <chrono>
#include <cmath>
#include <future>

#include <gtest/gtest.h>
#include <nav_msgs/GetPlan.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>

#include "test_support.h"

namespace roomba_rrt::planner_node_test {
namespace {

constexpr double kResolution = 0.05;  // m, the map's cells

// An 8 m x 6 m room at 5 cm with a wall across it from x = 4 m, open for its top metre: plans
// from the left half to the right half go around it.
nav_msgs::OccupancyGrid wallMap() {
  nav_msgs::OccupancyGrid map;
  map.header.frame_id = "map";
  map.info.resolution = kResolution;
  map.info.width = 160;
  map.info.height = 120;
  map.info.origin.orientation.w = 1;
  map.data.assign(map.info.width * map.info.height, 0);
  for (unsigned j = 0; j < map.info.height; ++j) {
    for (unsigned i = 0; i < map.info.width; ++i) {
      const bool border = i == 0 || j == 0 || i + 1 == map.info.width || j + 1 == map.info.height;
      const bool wall = i >= 80 && i < 84 && j < 100;
      if (border || wall) map.data[j * map.info.width + i] = 100;
    }
  }
  return map;
}

geometry_msgs::PoseStamped pose(double x, double y) {
  geometry_msgs::PoseStamped p;
  p.header.frame_id = "map";
  p.pose.position.x = x;
  p.pose.position.y = y;
  p.pose.orientation.w = 1;
  return p;
}

nav_msgs::GetPlan::Response makePlan(double x0, double y0, double x1, double y1) {
  nav_msgs::GetPlan srv;
  srv.request.start = pose(x0, y0);
  srv.request.goal = pose(x1, y1);
  EXPECT_TRUE(ros::service::call("/rrt_planner/make_plan", srv));
  return srv.response;
}

TEST(MakePlan, a_request_before_the_first_map_waits_for_it_then_plans_a_pose_every_cell) {
  ASSERT_TRUE(ros::service::waitForService("/rrt_planner/make_plan", ros::Duration(30)));
  // The request goes out first; the map follows a second later.
  std::future<nav_msgs::GetPlan::Response> answer =
      std::async(std::launch::async, [] { return makePlan(1, 1, 7, 1); });
  ros::WallDuration(1.0).sleep();
  ASSERT_EQ(answer.wait_for(std::chrono::seconds(0)), std::future_status::timeout)
      << "make_plan answered before any map was published";
  ros::NodeHandle nh;
  ros::Publisher map_pub = nh.advertise<nav_msgs::OccupancyGrid>("/map", 1, /*latch=*/true);
  map_pub.publish(wallMap());
  const nav_msgs::Path plan = answer.get().plan;
  ASSERT_FALSE(plan.poses.empty()) << "no plan once the map came";
  EXPECT_EQ(plan.header.frame_id, "map");
  // Around the wall (over 10 m, far more than the 2 to 4 vertices of an RRT path), a pose every
  // 5 cm at most, each facing the next one.
  const double length = sumOfSegments(plan);
  EXPECT_GT(length, 10.0);
  EXPECT_GE(plan.poses.size(), static_cast<std::size_t>(length / kResolution));
  for (std::size_t i = 1; i < plan.poses.size(); ++i) {
    const auto& a = plan.poses[i - 1].pose;
    const auto& b = plan.poses[i].pose;
    const double dx = b.position.x - a.position.x, dy = b.position.y - a.position.y;
    ASSERT_LE(std::hypot(dx, dy), kResolution + 1e-9) << "poses " << i - 1 << " and " << i;
    const double yaw = 2 * std::atan2(a.orientation.z, a.orientation.w);
    EXPECT_NEAR(std::remainder(yaw - std::atan2(dy, dx), 2 * M_PI), 0, 1e-6) << "pose " << i - 1;
  }
  const auto& last = plan.poses.back().pose.position;
  EXPECT_NEAR(last.x, 7, 1e-9);
  EXPECT_NEAR(last.y, 1, 1e-9);
}

}  // namespace
}  // namespace roomba_rrt::planner_node_test
