// rrt_planner planning in the simulator's furnished room (issue 9): what a user sees.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <ros/topic.h>
#include <visualization_msgs/MarkerArray.h>

#include "test_support.h"

namespace roomba_rrt::planner_node_test {
namespace {

constexpr double kRobotRadius = 0.17;  // config/roomba_world_furnished.yaml

struct Box {
  double min_x, min_y, max_x, max_y;
};
// The furniture of config/roomba_world_furnished.yaml, as a user reads it there.
constexpr Box kSofa{0.0, 0.0, 1.6, 0.6}, kCupboard{5.6, 0.4, 6.4, 1.9}, kBench{2.4, 3.9, 3.6, 4.3};

double distanceToBox(double x, double y, const Box& b) {
  const double dx = std::max({b.min_x - x, 0.0, x - b.max_x});
  const double dy = std::max({b.min_y - y, 0.0, y - b.max_y});
  return std::hypot(dx, dy);
}

// The smallest distance from (x, y) to a wall or a piece of furniture of the furnished room.
double clearance(double x, double y) {
  double d = std::min({x, y, 6.4 - x, 4.8 - y});
  for (const Box& b : {kSofa, kCupboard, kBench}) d = std::min(d, distanceToBox(x, y, b));
  d = std::min(d, std::hypot(x - 1.3, y - 3.5) - 0.30);  // round table
  d = std::min(d, std::hypot(x - 4.9, y - 3.3) - 0.20);  // bin
  return d;
}

geometry_msgs::Point point(double x, double y) {
  geometry_msgs::Point p;
  p.x = x;
  p.y = y;
  return p;
}

PlanPath::Request roomRequest(double goal_x, double goal_y) {
  PlanPath::Request request = scenarioRequest("room");
  request.start = point(3.2, 2.4);
  request.goal = point(goal_x, goal_y);
  request.collision_check = "segments";
  return request;
}

TEST(Room, the_issue_example_goes_around_the_bench_keeping_the_disc_clear) {
  const PlanPath::Response response = callPlanPath(roomRequest(3.0, 4.55));
  ASSERT_TRUE(response.success) << response.message;
  EXPECT_EQ(response.path.header.frame_id, "map");  // the simulator's frame
  ASSERT_GE(response.path.poses.size(), 2u);
  // Every point of every edge (sampled every centimetre) keeps the robot's disc clear.
  for (std::size_t i = 1; i < response.path.poses.size(); ++i) {
    const auto& a = response.path.poses[i - 1].pose.position;
    const auto& b = response.path.poses[i].pose.position;
    const int samples = 1 + static_cast<int>(std::hypot(b.x - a.x, b.y - a.y) / 0.01);
    for (int k = 0; k <= samples; ++k) {
      const double t = static_cast<double>(k) / samples;
      const double x = a.x + t * (b.x - a.x), y = a.y + t * (b.y - a.y);
      ASSERT_GE(clearance(x, y), kRobotRadius - 1e-9)
          << "edge " << i - 1 << " at " << x << ", " << y;
    }
  }
  const auto& last = response.path.poses.back().pose.position;
  EXPECT_LT(std::hypot(last.x - 3.0, last.y - 4.55), 1e-3);
  // The markers show the room's furniture: rectangles as CUBEs, in frame map.
  const auto markers =
      ros::topic::waitForMessage<visualization_msgs::MarkerArray>(kTreeTopic, ros::Duration(30));
  ASSERT_TRUE(markers);
  const auto* bench = findMarker(*markers, "rectangles", 2);
  ASSERT_NE(bench, nullptr);
  EXPECT_EQ(bench->type, visualization_msgs::Marker::CUBE);
  EXPECT_EQ(bench->header.frame_id, "map");
  EXPECT_DOUBLE_EQ(bench->scale.x, 1.2);
  EXPECT_NE(findMarker(*markers, "obstacles", 1), nullptr);  // the bin
}

TEST(Room, plans_from_the_fast_stream_unless_the_request_asks_for_matlabs) {
  PlanPath::Request request = roomRequest(3.0, 4.55);
  const PlanPath::Response by_default = callPlanPath(request);
  request.random_stream = "fast";
  const PlanPath::Response fast = callPlanPath(request);
  request.random_stream = "matlab";
  const PlanPath::Response matlab = callPlanPath(request);
  ASSERT_TRUE(by_default.success && fast.success && matlab.success);
  EXPECT_EQ(by_default.iterations, fast.iterations);
  EXPECT_EQ(by_default.length, fast.length);
  EXPECT_NE(matlab.length, fast.length);
}

TEST(Room, a_goal_inside_the_sofa_is_refused_naming_goal) {
  const PlanPath::Response response = callPlanPath(roomRequest(0.8, 0.3));
  EXPECT_FALSE(response.success);
  EXPECT_EQ(response.message.rfind("goal", 0), 0u) << response.message;
  EXPECT_NE(response.message.find("rectangles[0]"), std::string::npos) << response.message;
  EXPECT_TRUE(response.path.poses.empty());
}

TEST(Room, start_and_goal_are_required_and_the_world_gives_the_furniture) {
  PlanPath::Request request = scenarioRequest("room");
  EXPECT_EQ(callPlanPath(request).message.rfind("start: required", 0), 0u);
  request.start = point(3.2, 2.4);
  EXPECT_EQ(callPlanPath(request).message.rfind("goal: required", 0), 0u);
  request = roomRequest(3.0, 4.55);
  request.rectangles.resize(1);
  EXPECT_EQ(callPlanPath(request).message.rfind("scenario", 0), 0u);
}

TEST(Room, a_bigger_robot_or_clearance_refuses_a_goal_the_roomba_reaches) {
  PlanPath::Request request = roomRequest(3.0, 4.55);  // 0.25 from the wall and the bench
  request.clearance = 0.1;
  const PlanPath::Response response = callPlanPath(request);
  EXPECT_FALSE(response.success);
  EXPECT_EQ(response.message.rfind("goal", 0), 0u) << response.message;
}

TEST(Rectangles, explicit_rectangles_are_planned_around_and_bad_ones_named) {
  PlanPath::Request request;
  request.start = point(1, 5);
  request.goal = point(9, 5);
  request.collision_check = "segments";
  request.max_iterations = 20000;
  RectangleObstacle wall;
  wall.min_x = 4;
  wall.min_y = 1;
  wall.max_x = 6;
  wall.max_y = 9;
  request.rectangles.push_back(wall);
  const PlanPath::Response response = callPlanPath(request);
  ASSERT_TRUE(response.success) << response.message;
  EXPECT_GT(response.length, 2 * std::hypot(3.0, 4.0));  // over or under the wall
  request.rectangles.push_back(wall);
  request.rectangles.push_back(wall);
  request.rectangles[2].max_x = 3;  // inverted
  EXPECT_EQ(callPlanPath(request).message.rfind("rectangles[2].max_x", 0), 0u);
  request.rectangles[2].max_x = std::nan("");
  EXPECT_EQ(callPlanPath(request).message.rfind("rectangles[2].max_x", 0), 0u);
}

}  // namespace
}  // namespace roomba_rrt::planner_node_test
