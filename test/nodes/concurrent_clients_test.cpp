// rrt_planner serving several clients at once (each call is its own connection, as separate
// client processes would open).
#include <algorithm>
#include <atomic>
#include <future>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>

#include "test_support.h"

namespace roomba_rrt::planner_node_test {
namespace {

// An iteration budget that keeps the node busy for a few seconds on this machine: a calibration
// (nothing is asserted about time), so the test neither takes minutes on a slow machine nor
// finishes the "long" plan before the short one starts on a fast one.
int iterationsLastingSeconds(double seconds) {
  constexpr int kProbe = 100'000;
  const ros::WallTime begin = ros::WallTime::now();
  callPlanPath(unreachableGoal(kProbe));
  const double probe_seconds = std::max(1e-3, (ros::WallTime::now() - begin).toSec());
  return static_cast<int>(std::clamp(kProbe * seconds / probe_seconds, 1.0 * kProbe, 5e6));
}

TEST(ConcurrentClients, a_long_plan_does_not_block_a_short_one_from_another_client) {
  const int long_iterations = iterationsLastingSeconds(3.0);
  std::atomic<int> finished{0};  // order in which the two calls came back
  int long_finished_as = 0;
  PlanPath::Response long_response;
  std::thread long_client([&] {
    long_response = callPlanPath(unreachableGoal(long_iterations));
    long_finished_as = ++finished;
  });
  // Give the long request time to reach the node and start planning.
  ros::WallDuration(0.5).sleep();
  const PlanPath::Response short_response = callPlanPath(scenarioRequest("a"));
  const int short_finished_as = ++finished;
  long_client.join();

  EXPECT_TRUE(short_response.success) << short_response.message;
  EXPECT_EQ(short_finished_as, 1) << "the short plan waited for the long one";
  EXPECT_EQ(long_finished_as, 2);
  EXPECT_FALSE(long_response.success);
  EXPECT_EQ(long_response.iterations, long_iterations);
  EXPECT_EQ(long_response.length, std::numeric_limits<double>::infinity());
}

TEST(ConcurrentClients, clients_calling_at_once_each_get_the_answer_to_their_own_request) {
  const std::vector<std::string> scenarios = {"a", "b", "c", "d"};
  std::vector<PlanPath::Response> alone;
  for (const std::string& name : scenarios) alone.push_back(callPlanPath(scenarioRequest(name)));

  std::vector<std::future<std::vector<PlanPath::Response>>> clients;
  for (const std::string& name : scenarios) {
    clients.push_back(std::async(std::launch::async, [name] {
      std::vector<PlanPath::Response> answers;
      for (int i = 0; i < 10; ++i) answers.push_back(callPlanPath(scenarioRequest(name)));
      return answers;
    }));
  }
  for (std::size_t c = 0; c < clients.size(); ++c) {
    for (const PlanPath::Response& answer : clients[c].get()) {
      EXPECT_EQ(answer.success, alone[c].success) << scenarios[c];
      EXPECT_EQ(answer.length, alone[c].length) << scenarios[c];
      EXPECT_EQ(answer.tree_size, alone[c].tree_size) << scenarios[c];
    }
  }
}

}  // namespace
}  // namespace roomba_rrt::planner_node_test
