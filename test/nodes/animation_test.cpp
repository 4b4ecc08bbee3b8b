// rrt_planner with ~animate: rviz sees the tree grow while the plan runs.
#include <mutex>
#include <vector>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <visualization_msgs/MarkerArray.h>

#include "test_support.h"

namespace roomba_rrt::planner_node_test {
namespace {

TEST(Animation, the_tree_is_published_growing_before_the_final_plan) {
  ros::NodeHandle nh;
  std::mutex mutex;
  std::vector<std::size_t> edge_points;  // per received MarkerArray
  std::size_t frames_with_path = 0;
  const boost::function<void(const visualization_msgs::MarkerArrayConstPtr&)> record =
      [&](const visualization_msgs::MarkerArrayConstPtr& markers) {
        const std::lock_guard<std::mutex> lock(mutex);
        const auto* edges = findMarker(*markers, "edges");
        edge_points.push_back(edges == nullptr ? 0 : edges->points.size());
        if (findMarker(*markers, "path") != nullptr) ++frames_with_path;
      };
  const ros::Subscriber sub =
      nh.subscribe<visualization_msgs::MarkerArray>(kTreeTopic, 1000, record);
  ros::AsyncSpinner spinner(1);
  spinner.start();
  for (int i = 0; i < 100 && sub.getNumPublishers() == 0; ++i) ros::WallDuration(0.05).sleep();
  ASSERT_EQ(sub.getNumPublishers(), 1u);

  const PlanPath::Response response = callPlanPath(scenarioRequest("a"));
  ASSERT_TRUE(response.success) << response.message;
  const std::size_t final_edge_points = 2 * (response.tree_size - 1);
  for (int i = 0; i < 100; ++i) {  // wait for the final markers to arrive
    {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!edge_points.empty() && edge_points.back() == final_edge_points) break;
    }
    ros::WallDuration(0.05).sleep();
  }

  const std::lock_guard<std::mutex> lock(mutex);
  ASSERT_FALSE(edge_points.empty());
  EXPECT_EQ(edge_points.back(), final_edge_points);
  EXPECT_EQ(frames_with_path, 1u) << "only the finished plan has a path";
  // Frames during planning: every 20 iterations, each a larger tree than the one before.
  std::size_t growing = 0;
  for (std::size_t i = 1; i < edge_points.size(); ++i) {
    EXPECT_LE(edge_points[i - 1], edge_points[i]) << "frame " << i;
    growing += edge_points[i - 1] < edge_points[i];
  }
  EXPECT_GE(growing, 3u) << "expected the tree to grow over several frames";
}

}  // namespace
}  // namespace roomba_rrt::planner_node_test
