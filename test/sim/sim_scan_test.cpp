// roomba_sim's range sensors through a real master (sim_scan.test: the furnished room, one robot
// at 10x real time; sim_scan_two_robots.test: two named robots at 3x): the LDS preset's
// sensor_msgs/LaserScan on /[<robot>/]scan in frame [<robot>/]base_scan, 5 scans per simulated
// second stamped in simulated time, REP 117 ranges that see the room (and the other robot), and
// the static base_link → base_scan in tf.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <cmath>
#include <string>
#include <vector>

#include "../common/wait_until.h"

namespace {

using roomba_rrt::test::waitUntil;

TEST(SimScan, the_lds_scans_at_its_rate_in_simulated_time_and_sees_the_room) {
  ros::NodeHandle nh, pnh("~");
  const std::string prefix = pnh.param<std::string>("prefix", "");
  const double ahead = pnh.param("ahead", 0.0), left = pnh.param("left", 0.0);
  std::vector<sensor_msgs::LaserScan> scans;
  double clock = 0;
  ros::Subscriber clock_sub = nh.subscribe<rosgraph_msgs::Clock>(
      "/clock", 1000,
      [&](const rosgraph_msgs::Clock::ConstPtr& msg) { clock = msg->clock.toSec(); });
  ros::Subscriber sub = nh.subscribe<sensor_msgs::LaserScan>(
      "/" + prefix + "scan", 100, [&](const sensor_msgs::LaserScan::ConstPtr& msg) {
        EXPECT_LE(msg->header.stamp.toSec(), clock + 1e-9) << "stamped after /clock";
        scans.push_back(*msg);
      });
  ASSERT_TRUE(waitUntil([&] { return scans.size() >= 15; }, 60.0)) << scans.size() << " scans";

  for (std::size_t k = 0; k < scans.size(); ++k) {
    const sensor_msgs::LaserScan& scan = scans[k];
    EXPECT_EQ(scan.header.frame_id, prefix + "base_scan");
    ASSERT_EQ(scan.ranges.size(), 360u);
    EXPECT_FLOAT_EQ(scan.angle_min, 0.0f);
    EXPECT_FLOAT_EQ(scan.angle_increment, static_cast<float>(M_PI / 180));
    EXPECT_FLOAT_EQ(scan.angle_max, static_cast<float>(2 * M_PI * 359 / 360));
    EXPECT_FLOAT_EQ(scan.range_min, 0.12f);
    EXPECT_FLOAT_EQ(scan.range_max, 3.5f);
    EXPECT_FLOAT_EQ(scan.scan_time, 0.2f);
    // Simulated time: 5 Hz exactly, on the simulator's steps, none lost.
    const double stamp = scan.header.stamp.toSec();
    EXPECT_NEAR(stamp * 5, std::round(stamp * 5), 1e-6) << stamp;
    if (k > 0) {
      EXPECT_NEAR(stamp - scans[k - 1].header.stamp.toSec(), 0.2, 1e-6);
    }
    for (float r : scan.ranges) {
      EXPECT_TRUE(std::isinf(r) || (r >= 0.12f && r <= 3.5f)) << r;
    }
    // The robot stands still (no /cmd_vel): ahead and to its left, what the world file says.
    EXPECT_NEAR(scan.ranges[0], ahead, 1e-5);
    EXPECT_NEAR(scan.ranges[90], left, 1e-5);
  }

  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  geometry_msgs::TransformStamped mount;
  ASSERT_TRUE(waitUntil(
      [&] {
        return buffer.canTransform(prefix + "base_link", prefix + "base_scan", ros::Time(0)) &&
               buffer.canTransform("map", prefix + "base_scan", ros::Time(0));
      },
      10.0));
  mount = buffer.lookupTransform(prefix + "base_link", prefix + "base_scan", ros::Time(0));
  EXPECT_DOUBLE_EQ(mount.transform.translation.x, 0);
  EXPECT_DOUBLE_EQ(mount.transform.rotation.w, 1);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "sim_scan_test");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
