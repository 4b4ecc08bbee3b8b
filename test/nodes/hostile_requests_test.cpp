// rrt_planner under issue 11's hostile requests: each is answered (refused naming the field,
// stopped by the time budget, or planned), and the node plans scenario a right afterwards.
// The node runs with ~threads 2 and ~max_planning_time 2 (hostile_requests.test).
#include <algorithm>
#include <atomic>
#include <future>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>

#include "test_support.h"

namespace roomba_rrt::planner_node_test {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One request of the issue and how the node must answer it.
struct Hostile {
  std::string what;
  PlanPath::Request request;
  std::string message_start;  // the answer's message starts with this (success false)
  std::string or_start = "";  // ... or with this, when a fast machine gets there first
};

PlanPath::Request withBounds(double x_min, double x_max, double y_min, double y_max) {
  PlanPath::Request r;
  r.x_min = x_min;
  r.x_max = x_max;
  r.y_min = y_min;
  r.y_max = y_max;
  return r;
}

PlanPath::Request hugeBounds(const std::string& algorithm) {
  PlanPath::Request r = withBounds(-8e307, 8e307, -8e307, 8e307);
  r.start = point(1, 1);
  r.goal = point(9, 9);
  r.step = 1e308;
  r.max_iterations = 1000;
  r.algorithm = algorithm;
  return r;
}

PlanPath::Request denormalBounds(bool along_x, bool with_obstacle) {
  PlanPath::Request r = along_x ? withBounds(0, 1e-320, 0, 1) : withBounds(0, 1, 0, 1e-320);
  r.start = along_x ? point(0, 0.05) : point(0.05, 0);  // (0, 0) would mean "default"
  r.goal = along_x ? point(0, 0.95) : point(0.95, 0);
  if (with_obstacle) {
    r.obstacles = {along_x ? circle(0, 0.5, 0.2) : circle(0.5, 0, 0.2)};
  } else {
    r.goal_bias = 1e-9;
    r.step = 0.001;
  }
  r.max_iterations = 5000;
  return r;
}

std::vector<Hostile> hostileRequests() {
  std::vector<Hostile> all;
  for (const char* algorithm : {"rrt", "rrt_connect", "rrt_star"}) {
    all.push_back(
        {std::string("huge bounds, ") + algorithm, hugeBounds(algorithm), "bounds.x_min"});
  }
  all.push_back({"denormal x bounds", denormalBounds(true, true), "bounds: width"});
  all.push_back({"denormal y bounds", denormalBounds(false, true), "bounds: width"});
  all.push_back({"denormal bounds, no obstacle", denormalBounds(true, false), "bounds: width"});
  PlanPath::Request steer = withBounds(0, 1e308, 0, 10);
  steer.start = point(1, 1);
  steer.goal = point(9, 9);
  steer.step = 2.0;
  steer.goal_bias = 1e-9;
  steer.max_iterations = 50000;
  all.push_back({"steer overflow", steer, "bounds.x_max"});
  PlanPath::Request far = withBounds(-1e100, 1e100, -1e100, 1e100);
  far.start = point(1, 1);
  far.goal = point(5e99, 9);
  far.algorithm = "rrt_connect";
  all.push_back({"far goal, rrt_connect", far, "bounds.x_min"});
  PlanPath::Request tiny_step = scenarioRequest("a");
  tiny_step.algorithm = "rrt_connect";
  tiny_step.step = 1e-12;
  all.push_back({"rrt_connect, step 1e-12", tiny_step, "step"});
  PlanPath::Request one_iteration = scenarioRequest("a");
  one_iteration.algorithm = "rrt_connect";
  one_iteration.step = 1e-6;
  one_iteration.max_iterations = 1;
  all.push_back({"rrt_connect, step 1e-6, one iteration", one_iteration, "no path within 1 "});
  PlanPath::Request small_step = scenarioRequest("a");
  small_step.algorithm = "rrt_connect";
  small_step.step = 1e-4;
  all.push_back({"rrt_connect, step 1e-4", small_step, "no path within 1000 "});
  for (const char* algorithm : {"rrt", "rrt_connect", "rrt_star"}) {
    PlanPath::Request cap = unreachableGoal(5'000'000);
    cap.algorithm = algorithm;
    // 5 000 000 iterations take about 2 s: the budget stops the plan, or on a fast, idle
    // machine the iterations run out first. Either way the answer is false with its reason.
    all.push_back({std::string("iteration cap, unreachable goal, ") + algorithm, cap,
                   "max_planning_time: the plan was stopped after 2 s",
                   "no path within 5000000 iterations"});
  }
  PlanPath::Request huge_radius = unreachableGoal(1000);
  huge_radius.obstacles[0].radius = 1e300;
  all.push_back({"radius 1e300", huge_radius, "obstacles[0].radius"});
  PlanPath::Request too_long = scenarioRequest("a");
  too_long.max_planning_time = 2.5;
  all.push_back({"max_planning_time above the node's", too_long, "max_planning_time"});
  PlanPath::Request nan_time = scenarioRequest("a");
  nan_time.max_planning_time = kNaN;
  all.push_back({"NaN max_planning_time", nan_time, "max_planning_time"});
  PlanPath::Request negative_time = scenarioRequest("a");
  negative_time.max_planning_time = -1;
  all.push_back({"negative max_planning_time", negative_time, "max_planning_time"});
  return all;
}

TEST(HostileRequests, each_is_answered_false_with_its_reason_and_the_node_then_plans_scenario_a) {
  for (const Hostile& hostile : hostileRequests()) {
    const PlanPath::Response answer = callPlanPath(hostile.request);
    EXPECT_FALSE(answer.success) << hostile.what;
    EXPECT_TRUE(answer.message.rfind(hostile.message_start, 0) == 0 ||
                (!hostile.or_start.empty() && answer.message.rfind(hostile.or_start, 0) == 0))
        << hostile.what << ": '" << answer.message << "'";
    EXPECT_TRUE(answer.path.poses.empty()) << hostile.what;
    const PlanPath::Response next = callPlanPath(scenarioRequest("a"));
    EXPECT_TRUE(next.success) << "after " << hostile.what << ": " << next.message;
  }
}

TEST(HostileRequests, a_start_at_the_goal_is_a_one_point_path_of_length_zero) {
  for (const char* algorithm : {"rrt", "rrt_star"}) {  // the issue: both answered false
    PlanPath::Request request;
    request.start = point(5, 5);
    request.goal = point(5, 5);
    request.algorithm = algorithm;
    const PlanPath::Response answer = callPlanPath(request);
    ASSERT_TRUE(answer.success) << algorithm << ": " << answer.message;
    ASSERT_EQ(answer.path.poses.size(), 1u) << algorithm;
    EXPECT_EQ(answer.path.poses[0].pose.position.x, 5.0);
    EXPECT_EQ(answer.length, 0.0) << algorithm;
  }
}

// Issue 20, item 1: long plans that take every thread no longer deny the service. Eight hostile
// clients keep asking for unreachable plans at the request cap (each runs until the node's 2 s
// budget, two threads); meanwhile ordinary requests are planned, each within its own budget plus
// about 0.1 s (the oldest long plan gives up its thread), never answered "busy".
TEST(HostileRequests, eight_clients_with_long_plans_cannot_starve_an_ordinary_request) {
  std::atomic<bool> stop{false};
  std::atomic<int> preempted{0}, hostile_answers{0};
  std::vector<std::future<void>> hostile;
  for (int i = 0; i < 8; ++i) {
    hostile.push_back(std::async(std::launch::async, [&] {
      while (!stop) {
        const PlanPath::Response answer = callPlanPath(unreachableGoal(5'000'000));
        ++hostile_answers;
        if (answer.message.rfind("preempted", 0) == 0) ++preempted;
      }
    }));
  }
  ros::WallDuration(0.5).sleep();  // every thread taken by now
  std::vector<double> latencies;
  for (int i = 0; i < 30; ++i) {
    const ros::WallTime t0 = ros::WallTime::now();
    const PlanPath::Response answer = callPlanPath(scenarioRequest("a"));
    latencies.push_back((ros::WallTime::now() - t0).toSec());
    EXPECT_TRUE(answer.success) << "ordinary request " << i << ": " << answer.message;
    ros::WallDuration(0.05).sleep();
  }
  stop = true;
  for (auto& client : hostile) client.get();
  std::sort(latencies.begin(), latencies.end());
  const double worst = latencies.back();
  // In the test's XML (build/test_results/roomba_rrt/rosunit-hostile_requests.xml).
  RecordProperty("ordinary_median_ms", static_cast<int>(1000 * latencies[latencies.size() / 2]));
  RecordProperty("ordinary_worst_ms", static_cast<int>(1000 * worst));
  RecordProperty("hostile_answers", hostile_answers.load());
  RecordProperty("hostile_preempted", preempted.load());
  // Its own plan takes milliseconds; its budget is the node's 2 s. Generous bound for a loaded
  // machine, far below the 2 s that a refusal or a wait behind the long plans would take.
  EXPECT_LT(worst, 1.0);
  EXPECT_GT(preempted.load(), 0) << "no long plan gave up its thread";
  const PlanPath::Response after = callPlanPath(scenarioRequest("a"));
  EXPECT_TRUE(after.success) << after.message;
}

}  // namespace
}  // namespace roomba_rrt::planner_node_test
