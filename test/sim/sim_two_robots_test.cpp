// Issue 13 through a real master: two named robots in one roomba_sim, each driven by its own
// roomba_fsm in its namespace (sim_two_robots.test). Both move, each has its own tf tree under
// map (robot1/odom → robot1/base_link, robot2/…; no bare base_link), one node publishes /clock,
// and the two discs never overlap.
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <xmlrpcpp/XmlRpc.h>

#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "../common/wait_until.h"

namespace {

using roomba_rrt::test::waitUntil;

/// What one robot's /<name>/odom said.
struct Track {
  bool started = false;
  double x0 = 0, y0 = 0, x = 0, y = 0, farthest = 0;
  std::string frame, child;
  long count = 0;
};

/// The nodes publishing `topic`, from the master.
std::vector<std::string> publishersOf(const std::string& topic) {
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  std::vector<std::string> nodes;
  if (!ros::master::execute("getSystemState", request, response, payload, true)) return nodes;
  XmlRpc::XmlRpcValue& publications = payload[0];
  for (int i = 0; i < publications.size(); ++i) {
    if (static_cast<std::string>(publications[i][0]) != topic) continue;
    for (int j = 0; j < publications[i][1].size(); ++j) {
      nodes.push_back(static_cast<std::string>(publications[i][1][j]));
    }
  }
  return nodes;
}

TEST(TwoRobots, both_move_with_separate_tf_trees_one_clock_and_no_overlap) {
  ros::NodeHandle nh;
  std::map<std::string, Track> tracks;
  std::map<double, std::map<std::string, std::pair<double, double>>> by_stamp;
  double closest = INFINITY;
  std::vector<ros::Subscriber> subs;
  for (const std::string name : {"robot1", "robot2"}) {
    subs.push_back(nh.subscribe<nav_msgs::Odometry>(
        "/" + name + "/odom", 1000, [&, name](const nav_msgs::Odometry::ConstPtr& msg) {
          Track& t = tracks[name];
          const double x = msg->pose.pose.position.x, y = msg->pose.pose.position.y;
          if (!t.started) {
            t.started = true;
            t.x0 = x;
            t.y0 = y;
          }
          t.x = x;
          t.y = y;
          t.farthest = std::max(t.farthest, std::hypot(x - t.x0, y - t.y0));
          t.frame = msg->header.frame_id;
          t.child = msg->child_frame_id;
          ++t.count;
          // Both robots' poses of the same step: their centres at least two radii apart.
          auto& step = by_stamp[msg->header.stamp.toSec()];
          step[name] = {x, y};
          if (step.size() == 2) {
            closest = std::min(closest, std::hypot(step["robot1"].first - step["robot2"].first,
                                                   step["robot1"].second - step["robot2"].second));
            by_stamp.erase(msg->header.stamp.toSec());
          }
        }));
  }
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);

  // 60 s of robot time at 10x: each FSM drives forward, spirals and bumps.
  ASSERT_TRUE(waitUntil(
      [&] { return tracks["robot1"].farthest > 1.0 && tracks["robot2"].farthest > 1.0; }, 60))
      << "robot1 moved " << tracks["robot1"].farthest << " m, robot2 " << tracks["robot2"].farthest
      << " m";
  for (const std::string name : {"robot1", "robot2"}) {
    EXPECT_EQ(tracks[name].frame, name + "/odom");
    EXPECT_EQ(tracks[name].child, name + "/base_link");
  }
  waitUntil([] { return false; }, 3.0);  // more steps, more chances to meet
  EXPECT_GE(closest, 0.34 - 1e-6);

  ASSERT_TRUE(waitUntil(
      [&] {
        return buffer.canTransform("map", "robot1/base_link", ros::Time(0)) &&
               buffer.canTransform("map", "robot2/base_link", ros::Time(0));
      },
      20));
  const auto r1 = buffer.lookupTransform("robot1/odom", "robot1/base_link", ros::Time(0));
  const auto r2 = buffer.lookupTransform("robot2/odom", "robot2/base_link", ros::Time(0));
  EXPECT_GT(std::hypot(r1.transform.translation.x - r2.transform.translation.x,
                       r1.transform.translation.y - r2.transform.translation.y),
            0.34 - 1e-3);
  EXPECT_FALSE(buffer._frameExists("base_link")) << buffer.allFramesAsString();
  EXPECT_FALSE(buffer._frameExists("odom")) << buffer.allFramesAsString();

  const std::vector<std::string> clocks = publishersOf("/clock");
  ASSERT_EQ(clocks.size(), 1u);
  EXPECT_EQ(clocks[0], "/roomba_sim");
  EXPECT_TRUE(publishersOf("/odom").empty());  // no unnamed robot
  // Each FSM found its robot's topics by its namespace alone.
  EXPECT_EQ(publishersOf("/robot1/cmd_vel"), std::vector<std::string>{"/robot1/roomba_fsm"});
  EXPECT_EQ(publishersOf("/robot2/cmd_vel"), std::vector<std::string>{"/robot2/roomba_fsm"});
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "sim_two_robots_test");
  ros::NodeHandle nh;  // start the node before the test
  return RUN_ALL_TESTS();
}
