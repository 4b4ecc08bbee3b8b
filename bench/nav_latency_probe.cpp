// Goal to motion over ROS: wall time from a goal on /move_base_simple/goal to the first non-zero
// /cmd_vel of roomba_bt running config/roomba_nav_tree.xml (roomba_sim, rrt_planner and roomba_bt
// must be running; scripts/bench starts them at real-time factor 1 in the furnished room).
//
//   nav_latency_probe [--goals N] [--json]
//
// Each sample: cancel (/move_base/cancel), wait until /cmd_vel has been zero for 0.3 s, publish a
// goal, time the first non-zero /cmd_vel, let the robot drive 0.3 s. Goals cycle through four
// points of the furnished room, so every sample plans anew. Prints p50, p90 and max in ms.
#include <actionlib_msgs/GoalID.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

namespace {

std::mutex mutex;
ros::WallTime armed_at, first_motion, last_motion;
bool armed = false;

void onCommand(const geometry_msgs::Twist& cmd) {
  const ros::WallTime now = ros::WallTime::now();
  if (cmd.linear.x == 0 && cmd.angular.z == 0) return;
  std::lock_guard<std::mutex> lock(mutex);
  last_motion = now;
  if (armed && first_motion.isZero()) first_motion = now;
}

double percentile(std::vector<double> values, double p) {
  std::sort(values.begin(), values.end());
  const std::size_t i = std::min(values.size() - 1, static_cast<std::size_t>(p * values.size()));
  return values[i];
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "nav_latency_probe", ros::init_options::AnonymousName);
  int goals = 40;
  bool json = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--goals") && i + 1 < argc) {
      goals = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--json")) {
      json = true;
    } else {
      const bool help = !std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h");
      std::fprintf(help ? stdout : stderr, "usage: nav_latency_probe [--goals N] [--json]\n");
      return help ? 0 : 2;
    }
  }
  if (goals < 1) {
    std::fprintf(stderr, "nav_latency_probe: --goals must be >= 1\n");
    return 2;
  }
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(1);
  spinner.start();
  ros::Subscriber sub =
      nh.subscribe("/cmd_vel", 100, onCommand, ros::TransportHints().tcpNoDelay());
  ros::Publisher goal_pub = nh.advertise<geometry_msgs::PoseStamped>("/move_base_simple/goal", 1);
  ros::Publisher cancel_pub = nh.advertise<actionlib_msgs::GoalID>("/move_base/cancel", 1);
  const ros::WallTime connect_deadline = ros::WallTime::now() + ros::WallDuration(30.0);
  while (ros::ok() && (goal_pub.getNumSubscribers() == 0 || cancel_pub.getNumSubscribers() == 0 ||
                       sub.getNumPublishers() == 0)) {
    if (ros::WallTime::now() > connect_deadline) {
      std::fprintf(stderr, "nav_latency_probe: roomba_bt (navigation tree) is not running\n");
      return 1;
    }
    ros::WallDuration(0.05).sleep();
  }
  ros::WallDuration(0.5).sleep();

  const double points[][2] = {{1.2, 2.0}, {4.5, 2.4}, {2.5, 1.2}, {3.5, 3.3}};
  std::vector<double> latencies_ms;
  int missed = 0;
  for (int n = 0; n < goals && ros::ok(); ++n) {
    cancel_pub.publish(actionlib_msgs::GoalID());
    // Stopped: no non-zero command for 0.3 s.
    for (;;) {
      ros::WallDuration(0.05).sleep();
      std::lock_guard<std::mutex> lock(mutex);
      if ((ros::WallTime::now() - last_motion).toSec() > 0.3) break;
    }
    geometry_msgs::PoseStamped goal;
    goal.header.frame_id = "map";
    goal.pose.position.x = points[n % 4][0];
    goal.pose.position.y = points[n % 4][1];
    goal.pose.orientation.w = 1;
    {
      std::lock_guard<std::mutex> lock(mutex);
      first_motion = ros::WallTime();
      armed = true;
      armed_at = ros::WallTime::now();
    }
    goal_pub.publish(goal);
    ros::WallTime moved;
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(5.0);
    while (ros::ok() && ros::WallTime::now() < deadline) {
      {
        std::lock_guard<std::mutex> lock(mutex);
        moved = first_motion;
      }
      if (!moved.isZero()) break;
      ros::WallDuration(0.0005).sleep();
    }
    std::lock_guard<std::mutex> lock(mutex);
    armed = false;
    if (moved.isZero()) {
      ++missed;
    } else {
      latencies_ms.push_back((moved - armed_at).toSec() * 1e3);
    }
    ros::WallDuration(0.3).sleep();
  }
  cancel_pub.publish(actionlib_msgs::GoalID());
  ros::WallDuration(0.1).sleep();
  if (latencies_ms.empty()) {
    std::fprintf(stderr, "nav_latency_probe: the robot never moved (%d goals)\n", missed);
    return 1;
  }
  const double p50 = percentile(latencies_ms, 0.5), p90 = percentile(latencies_ms, 0.9),
               max = percentile(latencies_ms, 1.0);
  if (json) {
    std::printf(
        "{\"goals\": %zu, \"missed\": %d, \"p50_ms\": %.2f, \"p90_ms\": %.2f, "
        "\"max_ms\": %.2f}\n",
        latencies_ms.size(), missed, p50, p90, max);
  } else {
    std::printf(
        "goal -> first non-zero /cmd_vel over %zu goals (%d without motion within 5 s): "
        "p50 %.1f ms, p90 %.1f ms, max %.1f ms (wall time)\n",
        latencies_ms.size(), missed, p50, p90, max);
  }
  return 0;
}
