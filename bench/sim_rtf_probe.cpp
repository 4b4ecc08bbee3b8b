// Measures roomba_sim's sustained real-time factor as a subscriber that reads every /odom sees it:
// simulated seconds (from the /odom stamps) per wall second, and how many messages were missed.
//
//   rosparam set /use_sim_time true
//   rosrun roomba_rrt roomba_sim _real_time_factor:=50 &
//   rosrun roomba_rrt sim_rtf_probe 20        # wall seconds to listen (default 10)
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

struct Tally {
  long received = 0;
  long missed = 0;  ///< steps whose /odom never arrived (gaps in the stamps)
  double first_stamp = 0, last_stamp = 0;
  ros::WallTime first_wall, last_wall;
  double step = 1.0 / 60.0;

  void onOdom(const nav_msgs::Odometry& msg) {
    const double stamp = msg.header.stamp.toSec();
    const ros::WallTime now = ros::WallTime::now();
    if (received == 0) {
      first_stamp = stamp;
      first_wall = now;
    } else {
      const long steps = std::lround((stamp - last_stamp) / step);
      if (steps > 1) missed += steps - 1;
    }
    last_stamp = stamp;
    last_wall = now;
    ++received;
  }
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "sim_rtf_probe", ros::init_options::AnonymousName);
  const double listen = argc > 1 ? std::atof(argv[1]) : 10.0;
  ros::NodeHandle nh;
  Tally tally;
  tally.step = ros::param::param("/roomba_sim/step", 1.0 / 60.0);
  ros::Subscriber sub =
      nh.subscribe("/odom", 10000, &Tally::onOdom, &tally, ros::TransportHints().tcpNoDelay());
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(listen);
  while (ros::ok() && ros::WallTime::now() < end) {
    ros::spinOnce();
    ros::WallDuration(0.0005).sleep();
  }
  const double wall = (tally.last_wall - tally.first_wall).toSec();
  if (tally.received < 2 || wall <= 0) {
    std::fprintf(stderr, "sim_rtf_probe: no /odom received (is roomba_sim running?)\n");
    return 1;
  }
  const double simulated = tally.last_stamp - tally.first_stamp;
  std::printf(
      "received %ld /odom (%.0f/s wall), missed %ld; %.1f s simulated in %.1f s wall: "
      "real-time factor %.1f\n",
      tally.received, tally.received / wall, tally.missed, simulated, wall, simulated / wall);
  return 0;
}
