// Measures roomba_sim's sustained real-time factor as a subscriber that reads every /odom sees it:
// simulated seconds (from the /odom stamps) per wall second, and how many messages were missed.
//
//   rosparam set /use_sim_time true
//   rosrun roomba_rrt roomba_sim _real_time_factor:=50 &
//   rosrun roomba_rrt sim_rtf_probe 20        # wall seconds to listen (default 10)
//
// With named robots (a world file with `robots:`), --robots N reads /robot1/odom .. /robotN/odom
// (scripts/run --robots and scripts/lib/place_robots.py name them so): one line per robot, then
// the totals, whose real-time factor is the slowest robot's; a robot that sends nothing fails.
//
//   rosrun roomba_rrt sim_rtf_probe 10 --robots 10
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <string>

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
  double wall() const { return (last_wall - first_wall).toSec(); }
  double simulated() const { return last_stamp - first_stamp; }
};

void print(const char* label, long received, long missed, double simulated, double wall,
           double factor) {
  std::printf(
      "%sreceived %ld /odom (%.0f/s wall), missed %ld; %.1f s simulated in %.1f s wall: "
      "real-time factor %.1f\n",
      label, received, received / wall, missed, simulated, wall, factor);
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "sim_rtf_probe", ros::init_options::AnonymousName);
  double listen = 10.0;
  int robots = 0;  // 0: the unnamed robot's /odom
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
      std::printf(
          "usage: sim_rtf_probe [SECONDS] [--robots N]\n"
          "  listens SECONDS of wall time (default 10) to /odom, or with --robots N to\n"
          "  /robot1/odom .. /robotN/odom, and prints the messages received and missed and the\n"
          "  real-time factor (with N robots: one line each, then the totals)\n");
      return 0;
    }
    if (std::strcmp(argv[i], "--robots") == 0 && i + 1 < argc) {
      robots = std::atoi(argv[++i]);
      if (robots < 1) {
        std::fprintf(stderr, "sim_rtf_probe: --robots needs a number >= 1\n");
        return 2;
      }
    } else {
      listen = std::atof(argv[i]);
    }
  }
  ros::NodeHandle nh;
  const double step = ros::param::param("/roomba_sim/step", 1.0 / 60.0);
  std::deque<Tally> tallies(std::max(robots, 1));  // stable addresses for the callbacks
  std::deque<ros::Subscriber> subs;
  for (int k = 0; k < static_cast<int>(tallies.size()); ++k) {
    tallies[k].step = step;
    const std::string topic = robots == 0 ? "/odom" : "/robot" + std::to_string(k + 1) + "/odom";
    subs.push_back(nh.subscribe(topic, 10000, &Tally::onOdom, &tallies[k],
                                ros::TransportHints().tcpNoDelay()));
  }
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(listen);
  while (ros::ok() && ros::WallTime::now() < end) {
    ros::spinOnce();
    ros::WallDuration(0.0005).sleep();
  }
  long received = 0, missed = 0;
  double factor = INFINITY, simulated = INFINITY, wall = 0;
  for (std::size_t k = 0; k < tallies.size(); ++k) {
    const Tally& t = tallies[k];
    const std::string name = robots == 0 ? "" : "robot" + std::to_string(k + 1);
    if (t.received < 2 || t.wall() <= 0) {
      std::fprintf(stderr, "sim_rtf_probe: no /%sodom received (is roomba_sim running%s?)\n",
                   robots == 0 ? "" : (name + "/").c_str(),
                   robots == 0 ? "" : " with a world file that names this robot");
      return 1;
    }
    if (robots > 0) {
      print(("/" + name + "/odom: ").c_str(), t.received, t.missed, t.simulated(), t.wall(),
            t.simulated() / t.wall());
    }
    received += t.received;
    missed += t.missed;
    factor = std::min(factor, t.simulated() / t.wall());
    simulated = std::min(simulated, t.simulated());
    wall = std::max(wall, t.wall());
  }
  print(robots == 0 ? "" : ("all " + std::to_string(robots) + " robots: ").c_str(), received,
        missed, simulated, wall, factor);
  return 0;
}
