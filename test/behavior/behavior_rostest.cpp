// roomba_fsm and roomba_bt through a real master.
//
// BehaviorInSim (roomba_fsm.test, roomba_bt.test): with roomba_sim at 10x real time, within
// 90 s of robot time the robot goes forward, spirals, bumps, backs up about 5 cm, rotates and
// drives on; ~state shows that sequence; the robot never leaves the room.
//
// BehaviorNodeStartup (roomba_behavior_startup.test, no simulator): without /bumper the node
// commands zero velocity; an invalid tree or parameter file stops the node at start with a
// message naming the element and line, or the parameter.
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <roomba_rrt/Bumper.h>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "../common/run_node.h"

namespace {

constexpr double kRoomWidth = 6.4, kRoomHeight = 4.8, kRadius = 0.17;

struct StateChange {
  std::string state;
  bool bumped_before;  ///< a pressed /bumper had been seen when the state was announced
};

/// Records ~state changes together with odometry and bumper.
class Observer {
 public:
  explicit Observer(const std::string& node) {
    ros::NodeHandle nh;
    state_sub_ = nh.subscribe("/" + node + "/state", 100, &Observer::onState, this);
    odom_sub_ = nh.subscribe("/odom", 100, &Observer::onOdom, this);
    bumper_sub_ = nh.subscribe("/bumper", 100, &Observer::onBumper, this);
  }

  std::vector<StateChange> changes;
  /// Distance driven backwards in each GoBack episode, from /odom (the applied command's sign
  /// and the pose), so that it does not depend on how ~state and /odom interleave.
  std::vector<double> backing_distances;
  double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
  int odom_count = 0;

  /// Index of the first occurrence of the lab's sequence: MoveForward, MoveInSpiral, (…),
  /// GoBack, Rotate, MoveForward; -1 when not (yet) seen. Returns the GoBack index.
  int labSequence() const {
    bool forward = false, spiral = false;
    for (std::size_t i = 0; i + 2 < changes.size(); ++i) {
      forward = forward || changes[i].state == "MoveForward";
      spiral = spiral || (forward && changes[i].state == "MoveInSpiral");
      if (spiral && changes[i].state == "GoBack" && changes[i + 1].state == "Rotate" &&
          changes[i + 2].state == "MoveForward") {
        return static_cast<int>(i);
      }
    }
    return -1;
  }

 private:
  void onState(const std_msgs::String& msg) { changes.push_back({msg.data, bumped_}); }
  void onOdom(const nav_msgs::Odometry& msg) {
    const double x = msg.pose.pose.position.x, y = msg.pose.pose.position.y;
    const bool backing = msg.twist.twist.linear.x < 0;
    // Standing still does not end a GoBack: on a loaded machine /bumper can be late at 10x real
    // time, and the node then commands zero velocity until it speaks again (the behaviour does
    // not tick meanwhile, and GoBack goes on afterwards). The next motion that is not backwards
    // (Rotate's turn) ends it.
    const bool still = msg.twist.twist.linear.x == 0 && msg.twist.twist.angular.z == 0;
    if (backing) backed_ += std::hypot(x - x_, y - y_);
    if (!backing && !still && backing_) {
      backing_distances.push_back(backed_);
      backed_ = 0;
    }
    backing_ = backing || (still && backing_);
    x_ = x;
    y_ = y;
    min_x = std::min(min_x, x_);
    max_x = std::max(max_x, x_);
    min_y = std::min(min_y, y_);
    max_y = std::max(max_y, y_);
    ++odom_count;
  }
  void onBumper(const roomba_rrt::Bumper& msg) { bumped_ = bumped_ || msg.pressed; }

  ros::Subscriber state_sub_, odom_sub_, bumper_sub_;
  double x_ = 0, y_ = 0, backed_ = 0;
  bool backing_ = false, bumped_ = false;
};

TEST(BehaviorInSim, forward_spiral_bump_back_rotate_and_drive_on_within_90_s_in_the_room) {
  const std::string node = ros::param::param<std::string>("~behavior_node", "roomba_fsm");
  Observer observer(node);

  // Wait for the simulated clock, then give the robot 90 s of robot time.
  const ros::WallTime wall_deadline = ros::WallTime::now() + ros::WallDuration(100.0);
  while (ros::Time::now().isZero() && ros::WallTime::now() < wall_deadline) {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  const ros::Time start = ros::Time::now();
  while (ros::ok() && (ros::Time::now() - start).toSec() < 90.0 &&
         ros::WallTime::now() < wall_deadline) {
    ros::spinOnce();
    if (observer.labSequence() >= 0) break;
    ros::WallDuration(0.002).sleep();
  }
  // /odom and ~state come over different connections: let the odometry catch up.
  const ros::WallTime settle = ros::WallTime::now() + ros::WallDuration(2.0);
  while (observer.backing_distances.empty() && ros::WallTime::now() < settle) {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }

  std::string seen;
  for (const auto& c : observer.changes) seen += c.state + " ";
  const int back = observer.labSequence();
  ASSERT_GE(back, 0) << "after " << (ros::Time::now() - start).toSec()
                     << " s of robot time, ~state showed: " << seen;
  EXPECT_TRUE(observer.changes[back].bumped_before) << "GoBack began without a bump";
  ASSERT_FALSE(observer.backing_distances.empty()) << "/odom never showed the robot backing up";
  const double backed = observer.backing_distances.front();
  EXPECT_NEAR(backed, 0.05, 0.015) << "GoBack should back up about 5 cm";
  std::printf(
      "%s: lab sequence complete after %.1f s of robot time, backed up %.3f m; ~state: %s\n",
      node.c_str(), (ros::Time::now() - start).toSec(), backed, seen.c_str());

  ASSERT_GT(observer.odom_count, 100);
  const double tolerance = 1e-3;
  EXPECT_GE(observer.min_x, kRadius - tolerance);
  EXPECT_LE(observer.max_x, kRoomWidth - kRadius + tolerance);
  EXPECT_GE(observer.min_y, kRadius - tolerance);
  EXPECT_LE(observer.max_y, kRoomHeight - kRadius + tolerance);
}

TEST(BehaviorNodeStartup, without_bumper_messages_the_node_commands_zero_velocity) {
  int commands = 0, moving = 0;
  ros::NodeHandle nh;
  ros::Subscriber sub = nh.subscribe<geometry_msgs::Twist>(
      "/cmd_vel", 100, [&](const geometry_msgs::Twist::ConstPtr& msg) {
        ++commands;
        if (msg->linear.x != 0 || msg->angular.z != 0) ++moving;
      });
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(3.0);
  while (ros::WallTime::now() < end && commands < 60) {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  EXPECT_GT(commands, 10) << "the node should keep commanding (zero) velocity";
  EXPECT_EQ(moving, 0);
}

using roomba_rrt::test::Outcome;

/// Runs a behaviour node binary with extra arguments and collects its exit code and output.
Outcome runNode(const std::string& type, const std::string& args) {
  return roomba_rrt::test::runNode(type, "startup_" + std::to_string(getpid()), args);
}

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = "/tmp/roomba_rrt_" + std::to_string(getpid()) + "_" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(BehaviorNodeStartup, an_invalid_tree_file_stops_roomba_bt_naming_element_and_line) {
  const std::string tree =
      writeTemp("tree.xml",
                "<root>\n<BehaviorTree>\n<Selector>\n<Dance/>\n</Selector>\n</BehaviorTree>\n"
                "</root>\n");
  const Outcome outcome = runNode("roomba_bt", "_tree_file:=" + tree);
  EXPECT_EQ(outcome.exit_code, 1) << outcome.output;
  EXPECT_NE(outcome.output.find(tree + ":4: <Dance>: unknown node type"), std::string::npos)
      << outcome.output;
  std::remove(tree.c_str());
}

TEST(BehaviorNodeStartup, an_invalid_parameter_file_stops_roomba_fsm_naming_the_parameter) {
  const std::string config = writeTemp("behavior.yaml", "angular_speed: -1\n");
  const Outcome outcome = runNode("roomba_fsm", "_config_file:=" + config);
  EXPECT_EQ(outcome.exit_code, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("angular_speed: must be in (0, 100], got -1"), std::string::npos)
      << outcome.output;
  std::remove(config.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "behavior_rostest");
  ros::NodeHandle nh;  // starts the node before the tests subscribe
  return RUN_ALL_TESTS();
}
