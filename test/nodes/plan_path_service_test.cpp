// rrt_planner through a real master: what a user sees when calling ~plan_path.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <ros/topic.h>
#include <visualization_msgs/MarkerArray.h>

#include "test_support.h"

namespace roomba_rrt::planner_node_test {
namespace {

using visualization_msgs::Marker;
using visualization_msgs::MarkerArray;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The latched message the node published last on `topic`.
template <typename Message>
Message latched(const std::string& topic) {
  const auto message = ros::topic::waitForMessage<Message>(topic, ros::Duration(30));
  if (!message) {
    ADD_FAILURE() << "nothing latched on " << topic;
    return Message();
  }
  return *message;
}

TEST(PlanPathService, scenario_a_by_name_goes_from_start_to_goal_with_length_the_sum_of_segments) {
  const PlanPath::Response response = callPlanPath(scenarioRequest("a"));
  ASSERT_TRUE(response.success) << response.message;
  ASSERT_GE(response.path.poses.size(), 2u);
  EXPECT_EQ(response.path.header.frame_id, "map");
  const auto& first = response.path.poses.front().pose.position;
  const auto& last = response.path.poses.back().pose.position;
  EXPECT_DOUBLE_EQ(first.x, 1.0);
  EXPECT_DOUBLE_EQ(first.y, 1.0);
  EXPECT_LT(std::hypot(last.x - 9.0, last.y - 9.0), 1e-3);  // the lab's epsilon
  EXPECT_NEAR(response.length, sumOfSegments(response.path), 1e-9);
  EXPECT_GT(response.iterations, 0);
  EXPECT_LE(response.iterations, 1000);  // the lab's maximum
  EXPECT_GE(response.tree_size, static_cast<int>(response.path.poses.size()));
  EXPECT_GE(response.planning_time, 0.0);
}

TEST(PlanPathService, the_same_request_gives_the_same_path) {
  const PlanPath::Response first = callPlanPath(scenarioRequest("b"));
  const PlanPath::Response second = callPlanPath(scenarioRequest("b"));
  EXPECT_EQ(first.success, second.success);
  EXPECT_EQ(first.iterations, second.iterations);
  EXPECT_EQ(first.tree_size, second.tree_size);
  EXPECT_EQ(first.length, second.length);
}

TEST(PlanPathService, the_labs_scenarios_draw_from_matlabs_stream_unless_asked_otherwise) {
  PlanPath::Request request = scenarioRequest("b");
  request.seed = 3;
  const PlanPath::Response by_default = callPlanPath(request);
  request.random_stream = "matlab";
  const PlanPath::Response matlab = callPlanPath(request);
  request.random_stream = "fast";
  const PlanPath::Response fast = callPlanPath(request);
  ASSERT_TRUE(by_default.success && matlab.success) << by_default.message << matlab.message;
  EXPECT_EQ(by_default.iterations, matlab.iterations);
  EXPECT_EQ(by_default.length, matlab.length);
  ASSERT_TRUE(fast.success) << fast.message;
  EXPECT_NE(fast.length, matlab.length);  // another stream, another tree
}

TEST(PlanPathService, tree_markers_hold_two_points_per_edge_and_replace_the_previous_plan) {
  ASSERT_TRUE(callPlanPath(scenarioRequest("b")).success);  // three obstacles
  const PlanPath::Response response = callPlanPath(scenarioRequest("a"));
  ASSERT_TRUE(response.success) << response.message;
  const MarkerArray markers = latched<MarkerArray>(kTreeTopic);
  ASSERT_FALSE(markers.markers.empty());
  EXPECT_EQ(markers.markers.front().action, Marker::DELETEALL);  // nothing of plan b stays
  for (const Marker& marker : markers.markers) EXPECT_EQ(marker.header.frame_id, "map");

  const Marker* edges = findMarker(markers, "edges");
  ASSERT_NE(edges, nullptr);
  EXPECT_EQ(edges->type, Marker::LINE_LIST);
  EXPECT_EQ(edges->points.size(), 2u * (response.tree_size - 1));
  const Marker* nodes = findMarker(markers, "nodes");
  ASSERT_NE(nodes, nullptr);
  EXPECT_EQ(nodes->type, Marker::POINTS);
  EXPECT_EQ(nodes->points.size(), static_cast<std::size_t>(response.tree_size));
  const Marker* path = findMarker(markers, "path");
  ASSERT_NE(path, nullptr);
  EXPECT_EQ(path->type, Marker::LINE_STRIP);
  EXPECT_EQ(path->points.size(), response.path.poses.size());
  const Marker* bounds = findMarker(markers, "bounds");
  ASSERT_NE(bounds, nullptr);
  EXPECT_EQ(bounds->type, Marker::LINE_STRIP);
  EXPECT_EQ(bounds->points.size(), 5u);  // closed rectangle

  // Scenario a has one obstacle: one cylinder of radius 1 at (5, 5), none left from plan b.
  const Marker* obstacle = findMarker(markers, "obstacles", 0);
  ASSERT_NE(obstacle, nullptr);
  EXPECT_EQ(obstacle->type, Marker::CYLINDER);
  EXPECT_DOUBLE_EQ(obstacle->pose.position.x, 5.0);
  EXPECT_DOUBLE_EQ(obstacle->scale.x, 2.0);
  EXPECT_EQ(findMarker(markers, "obstacles", 1), nullptr);
  for (const char* ns : {"start", "goal"}) {
    const Marker* sphere = findMarker(markers, ns);
    ASSERT_NE(sphere, nullptr) << ns;
    EXPECT_EQ(sphere->type, Marker::SPHERE) << ns;
  }

  const nav_msgs::Path latched_path = latched<nav_msgs::Path>(kPathTopic);
  EXPECT_EQ(latched_path.header.frame_id, "map");
  EXPECT_EQ(latched_path.poses.size(), response.path.poses.size());
}

// Every edge of a `segments` path must stay out of the disc (not just its end points).
void expectPathClearsCircle(const nav_msgs::Path& path, const CircleObstacle& c) {
  for (std::size_t i = 1; i < path.poses.size(); ++i) {
    const auto& a = path.poses[i - 1].pose.position;
    const auto& b = path.poses[i].pose.position;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double squared_length = dx * dx + dy * dy;
    const double t =
        squared_length == 0
            ? 0.0
            : std::clamp(((c.center.x - a.x) * dx + (c.center.y - a.y) * dy) / squared_length, 0.0,
                         1.0);
    EXPECT_GT(std::hypot(a.x + t * dx - c.center.x, a.y + t * dy - c.center.y), c.radius)
        << "edge " << i;
  }
}

TEST(PlanPathService, explicit_geometry_plans_with_every_algorithm_in_segments_mode) {
  for (const char* algorithm : {"rrt", "rrt_connect", "rrt_star"}) {
    PlanPath::Request request;
    request.start = point(1, 5);
    request.goal = point(9, 5);
    request.obstacles = {circle(5, 5, 1.5)};
    request.x_min = -1;
    request.x_max = 11;
    request.y_min = -1;
    request.y_max = 11;
    request.max_iterations = 5000;
    request.algorithm = algorithm;
    request.collision_check = "segments";
    const PlanPath::Response response = callPlanPath(request);
    ASSERT_TRUE(response.success) << algorithm << ": " << response.message;
    EXPECT_NEAR(response.length, sumOfSegments(response.path), 1e-9) << algorithm;
    SCOPED_TRACE(algorithm);
    expectPathClearsCircle(response.path, request.obstacles[0]);
  }
}

TEST(PlanPathService, a_plan_that_runs_out_of_iterations_fails_with_an_infinite_length) {
  PlanPath::Request request = scenarioRequest("d");
  request.max_iterations = 5;
  const PlanPath::Response response = callPlanPath(request);
  EXPECT_FALSE(response.success);
  EXPECT_TRUE(response.path.poses.empty());
  EXPECT_EQ(response.length, kInf);
  EXPECT_EQ(response.iterations, 5);
}

// One bad request: how it is made from a good one, and the field its error must name.
struct BadRequest {
  std::string what;
  std::function<void(PlanPath::Request&)> spoil;
  std::string field;
};

// A good explicit request: the lab's case a spelled out.
PlanPath::Request explicitCaseA() {
  PlanPath::Request request;
  request.start = point(1, 1);
  request.goal = point(9, 9);
  request.obstacles = {circle(5, 5, 1)};
  return request;
}

void setBounds(PlanPath::Request& r, double x_min, double x_max, double y_min, double y_max) {
  r.x_min = x_min;
  r.x_max = x_max;
  r.y_min = y_min;
  r.y_max = y_max;
}

std::vector<BadRequest> badRequests() {
  using R = PlanPath::Request;
  return {
      {"NaN start", [](R& r) { r.start.x = kNaN; }, "start"},
      {"infinite goal", [](R& r) { r.goal.y = kInf; }, "goal"},
      {"NaN start height", [](R& r) { r.start.z = kNaN; }, "start.z"},
      {"NaN obstacle centre", [](R& r) { r.obstacles[0].center.y = kNaN; }, "obstacles"},
      {"infinite bound", [](R& r) { r.x_max = kInf; }, "x_max"},
      {"NaN step", [](R& r) { r.step = kNaN; }, "step"},
      {"NaN goal bias", [](R& r) { r.goal_bias = kNaN; }, "goal_bias"},
      {"NaN tolerance", [](R& r) { r.goal_tolerance = kNaN; }, "goal_tolerance"},
      {"start outside the bounds", [](R& r) { r.start = point(11, 1); }, "start"},
      {"goal outside the bounds", [](R& r) { r.goal = point(9, -3); }, "goal"},
      {"start inside an obstacle", [](R& r) { r.start = point(5.5, 5); }, "start"},
      {"goal inside an obstacle", [](R& r) { r.goal = point(5, 4.5); }, "goal"},
      {"empty bounds", [](R& r) { setBounds(r, 5, 5, 0, 10); }, "x_"},
      {"inverted bounds", [](R& r) { setBounds(r, 0, 10, 10, 0.5); }, "y_"},
      {"negative step", [](R& r) { r.step = -0.2; }, "step"},
      {"goal bias above 1", [](R& r) { r.goal_bias = 1.5; }, "goal_bias"},
      {"negative goal bias", [](R& r) { r.goal_bias = -0.1; }, "goal_bias"},
      {"negative radius", [](R& r) { r.obstacles[0].radius = -1; }, "radius"},
      {"negative max_iterations", [](R& r) { r.max_iterations = -5; }, "max_iterations"},
      // config/rrt_planner.yaml: max_iterations_cap 5000000.
      {"max_iterations above the cap", [](R& r) { r.max_iterations = 5'000'001; },
       "max_iterations"},
      {"unknown algorithm", [](R& r) { r.algorithm = "dijkstra"; }, "algorithm"},
      {"unknown collision mode", [](R& r) { r.collision_check = "boxes"; }, "collision_check"},
      {"unknown random stream", [](R& r) { r.random_stream = "mt19937"; }, "random_stream"},
      {"unknown scenario", [](R& r) { r = scenarioRequest("z"); }, "scenario"},
      {"scenario with explicit geometry", [](R& r) { r.scenario = "a"; }, "scenario"},
  };
}

TEST(PlanPathService, every_bad_request_answers_false_naming_the_field_and_the_next_good_succeeds) {
  ASSERT_TRUE(callPlanPath(explicitCaseA()).success);
  for (const BadRequest& bad : badRequests()) {
    PlanPath::Request request = explicitCaseA();
    bad.spoil(request);
    const PlanPath::Response rejected = callPlanPath(request);
    EXPECT_FALSE(rejected.success) << bad.what;
    EXPECT_NE(rejected.message.find(bad.field), std::string::npos)
        << bad.what << ": message '" << rejected.message << "' does not name " << bad.field;
    EXPECT_EQ(rejected.length, kInf) << bad.what;
    EXPECT_TRUE(rejected.path.poses.empty()) << bad.what;

    const PlanPath::Response next = callPlanPath(scenarioRequest("a"));
    EXPECT_TRUE(next.success) << "after " << bad.what << ": " << next.message;
  }
}

}  // namespace
}  // namespace roomba_rrt::planner_node_test
