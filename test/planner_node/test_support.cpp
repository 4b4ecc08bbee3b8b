#include "test_support.h"

#include <cmath>

#include <gtest/gtest.h>
#include <ros/ros.h>

namespace roomba_rrt::planner_node_test {

PlanPath::Request scenarioRequest(const std::string& name) {
  PlanPath::Request request;
  request.scenario = name;
  return request;
}

PlanPath::Response callPlanPath(const PlanPath::Request& request) {
  PlanPath srv;
  srv.request = request;
  EXPECT_TRUE(ros::service::call(kService, srv)) << "the call to " << kService << " failed";
  return srv.response;
}

const visualization_msgs::Marker* findMarker(const visualization_msgs::MarkerArray& array,
                                             const std::string& ns, int id) {
  for (const auto& marker : array.markers) {
    if (marker.ns == ns && marker.id == id) return &marker;
  }
  return nullptr;
}

double sumOfSegments(const nav_msgs::Path& path) {
  double sum = 0;
  for (std::size_t i = 1; i < path.poses.size(); ++i) {
    const auto& a = path.poses[i - 1].pose.position;
    const auto& b = path.poses[i].pose.position;
    sum += std::hypot(b.x - a.x, b.y - a.y);
  }
  return sum;
}

}  // namespace roomba_rrt::planner_node_test

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "rrt_planner_test");
  ros::NodeHandle nh;
  if (!ros::service::waitForService(roomba_rrt::planner_node_test::kService, ros::Duration(60))) {
    ROS_FATAL_STREAM("rrt_planner never offered " << roomba_rrt::planner_node_test::kService);
    return 1;
  }
  return RUN_ALL_TESTS();
}
