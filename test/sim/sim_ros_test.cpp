// roomba_sim's messages without a master (src/ros/sim_ros.h): what rviz, tf and a behaviour
// node see of one unnamed robot and of named robots — frames, stamps, values, markers, the
// coverage map.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "../../src/ros/sim_ros.h"

namespace roomba_rrt::sim_node {
namespace {

using visualization_msgs::Marker;

const ros::Time kStamp(12, 500000000);

/// Two named robots in the lab's empty room (config/roomba_world_two_robots.yaml in code).
world::World twoRobots() {
  world::World world;
  world.robots = {{"robot1", {1.6, 2.4, 0.0}}, {"robot2", {4.8, 2.4, M_PI}}};
  return world;
}

/// The markers of one namespace, in order.
std::vector<Marker> inNamespace(const visualization_msgs::MarkerArray& array,
                                const std::string& ns) {
  std::vector<Marker> found;
  for (const Marker& m : array.markers) {
    if (m.ns == ns) found.push_back(m);
  }
  return found;
}

TEST(SimRos, the_unnamed_robot_uses_odom_and_base_link_a_named_one_its_prefix) {
  const RobotFrames unnamed = robotFrames("");
  EXPECT_EQ(unnamed.prefix, "");
  EXPECT_EQ(unnamed.odom, "odom");
  EXPECT_EQ(unnamed.base_link, "base_link");
  const RobotFrames named = robotFrames("robot2");
  EXPECT_EQ(named.prefix, "robot2/");
  EXPECT_EQ(named.odom, "robot2/odom");
  EXPECT_EQ(named.base_link, "robot2/base_link");
}

TEST(SimRos, odometry_is_the_pose_in_odom_and_the_applied_command_in_base_link) {
  const nav_msgs::Odometry odom =
      toOdometry({1.5, 2.5, M_PI_2}, {0.3, -0.7}, robotFrames("robot1"), kStamp);
  EXPECT_EQ(odom.header.stamp, kStamp);
  EXPECT_EQ(odom.header.frame_id, "robot1/odom");
  EXPECT_EQ(odom.child_frame_id, "robot1/base_link");
  EXPECT_DOUBLE_EQ(odom.pose.pose.position.x, 1.5);
  EXPECT_DOUBLE_EQ(odom.pose.pose.position.y, 2.5);
  EXPECT_DOUBLE_EQ(odom.pose.pose.position.z, 0.0);
  EXPECT_NEAR(odom.pose.pose.orientation.z, std::sqrt(0.5), 1e-15);  // 90° about z
  EXPECT_NEAR(odom.pose.pose.orientation.w, std::sqrt(0.5), 1e-15);
  EXPECT_DOUBLE_EQ(odom.twist.twist.linear.x, 0.3);
  EXPECT_DOUBLE_EQ(odom.twist.twist.angular.z, -0.7);
  EXPECT_DOUBLE_EQ(odom.twist.twist.linear.y, 0.0);
  for (double c : odom.pose.covariance) EXPECT_EQ(c, 0.0) << "odometry is perfect";
  for (double c : odom.twist.covariance) EXPECT_EQ(c, 0.0);
}

TEST(SimRos, the_bumper_is_stamped_in_base_link_with_its_sides) {
  const Bumper bumper = toBumper({true, false, true}, robotFrames(""), kStamp);
  EXPECT_EQ(bumper.header.stamp, kStamp);
  EXPECT_EQ(bumper.header.frame_id, "base_link");
  EXPECT_TRUE(bumper.pressed);
  EXPECT_FALSE(bumper.left);
  EXPECT_TRUE(bumper.right);
}

TEST(SimRos, tf_is_odom_to_base_link_at_the_pose_and_map_to_odom_the_identity) {
  const geometry_msgs::TransformStamped odom =
      toOdomTransform({2.0, 1.0, M_PI}, robotFrames("robot2"), kStamp);
  EXPECT_EQ(odom.header.stamp, kStamp);
  EXPECT_EQ(odom.header.frame_id, "robot2/odom");
  EXPECT_EQ(odom.child_frame_id, "robot2/base_link");
  EXPECT_DOUBLE_EQ(odom.transform.translation.x, 2.0);
  EXPECT_DOUBLE_EQ(odom.transform.translation.y, 1.0);
  EXPECT_NEAR(odom.transform.rotation.z, 1.0, 1e-15);
  EXPECT_NEAR(odom.transform.rotation.w, 0.0, 1e-15);

  const geometry_msgs::TransformStamped map = toMapTransform(robotFrames(""), kStamp);
  EXPECT_EQ(map.header.stamp, kStamp);
  EXPECT_EQ(map.header.frame_id, "map");
  EXPECT_EQ(map.child_frame_id, "odom");
  EXPECT_EQ(map.transform.translation.x, 0.0);
  EXPECT_EQ(map.transform.rotation.w, 1.0);
  EXPECT_EQ(map.transform.rotation.z, 0.0);
}

TEST(SimRos, a_scan_is_a_laser_scan_in_the_sensors_prefixed_frame_with_rep_117_ranges) {
  sensors::RangeSensorSpec ir = sensors::irBumperPreset(0.17);
  sensors::Scan scan;
  const float inf = std::numeric_limits<float>::infinity();
  scan.ranges = {0.1f, inf, -inf, 0.05f, inf, inf};
  const sensor_msgs::LaserScan msg = toLaserScan(ir, scan, robotFrames("robot2"), kStamp);
  EXPECT_EQ(msg.header.frame_id, "robot2/base_ir_bumper");
  EXPECT_EQ(msg.header.stamp, kStamp);
  EXPECT_FLOAT_EQ(msg.angle_min, static_cast<float>(-70 * M_PI / 180));
  EXPECT_FLOAT_EQ(msg.angle_max, static_cast<float>(70 * M_PI / 180));
  EXPECT_FLOAT_EQ(msg.angle_increment, static_cast<float>(28 * M_PI / 180));
  EXPECT_FLOAT_EQ(msg.scan_time, 0.05f);
  EXPECT_EQ(msg.time_increment, 0.0f);
  EXPECT_FLOAT_EQ(msg.range_max, 0.15f);
  EXPECT_EQ(msg.ranges, scan.ranges);
  EXPECT_TRUE(msg.intensities.empty());

  const geometry_msgs::TransformStamped mount =
      toSensorTransform(ir, robotFrames("robot2"), kStamp);
  EXPECT_EQ(mount.header.frame_id, "robot2/base_link");
  EXPECT_EQ(mount.child_frame_id, "robot2/base_ir_bumper");
  EXPECT_DOUBLE_EQ(mount.transform.translation.x, 0.17);
  EXPECT_EQ(toSensorTransform(sensors::ldsPreset(), robotFrames(""), kStamp).child_frame_id,
            "base_scan");
}

TEST(SimRos, coverage_is_the_fraction_as_a_float) {
  EXPECT_FLOAT_EQ(toCoverageMessage(0.25).data, 0.25f);
}

TEST(SimRos, coverage_map_shows_swept_floor_unswept_floor_and_furniture) {
  // A 1 m × 0.5 m room of 25 cm cells (4 × 2), a box over the top-right cell, and a 10 cm robot
  // whose disc covers only the centre of cell (0, 0).
  world::World world;
  world.room.width = 1.0;
  world.room.height = 0.5;
  world.coverage_cell_size = 0.25;
  world.robot().radius = 0.1;
  world.robot().initial_pose = {0.15, 0.15, 0.0};
  world.room.rectangles = {{0.75, 0.25, 1.0, 0.5}};
  const sim::MultiRobotSimulator sim(world);

  const nav_msgs::OccupancyGrid map = toCoverageMap(sim.unionCoverageGrid(), kStamp);
  EXPECT_EQ(map.header.frame_id, "map");
  EXPECT_EQ(map.header.stamp, kStamp);
  EXPECT_EQ(map.info.map_load_time, kStamp);
  EXPECT_EQ(map.info.width, 4u);
  EXPECT_EQ(map.info.height, 2u);
  EXPECT_FLOAT_EQ(map.info.resolution, 0.25f);
  EXPECT_EQ(map.info.origin.position.x, 0.0);
  EXPECT_EQ(map.info.origin.position.y, 0.0);
  EXPECT_EQ(map.info.origin.orientation.w, 1.0);
  // Row 0 is the bottom row: swept 0, unswept −1, furniture 100.
  const std::vector<std::int8_t> expected = {0, -1, -1, -1, -1, -1, -1, 100};
  EXPECT_EQ(map.data, expected);
}

TEST(SimRos, world_markers_are_four_walls_and_each_piece_of_furniture_in_map) {
  world::World world;
  world.room.circles = {{{1.3, 3.5}, 0.3}};
  world.room.rectangles = {{0.0, 0.0, 1.6, 0.6}};
  const std::vector<Marker> markers = worldMarkers(world);
  ASSERT_EQ(markers.size(), 6u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(markers[i].ns, "walls");
    EXPECT_EQ(markers[i].id, i);
    EXPECT_EQ(markers[i].type, Marker::CUBE);
  }
  // The right wall: 5 cm thick just outside x = 6.4, as long as the room plus both walls.
  EXPECT_NEAR(markers[1].pose.position.x, 6.425, 1e-12);
  EXPECT_NEAR(markers[1].scale.x, 0.05, 1e-12);
  EXPECT_NEAR(markers[1].scale.y, 4.9, 1e-12);
  EXPECT_EQ(markers[4].ns, "furniture");
  EXPECT_EQ(markers[4].id, 0);
  EXPECT_EQ(markers[4].type, Marker::CYLINDER);
  EXPECT_DOUBLE_EQ(markers[4].scale.x, 0.6);  // the table's diameter
  EXPECT_EQ(markers[5].ns, "furniture");
  EXPECT_EQ(markers[5].id, 1);
  EXPECT_EQ(markers[5].type, Marker::CUBE);
  EXPECT_DOUBLE_EQ(markers[5].pose.position.x, 0.8);  // the sofa's centre
  EXPECT_DOUBLE_EQ(markers[5].pose.position.y, 0.3);
  for (const Marker& m : markers) {
    EXPECT_EQ(m.header.frame_id, "map");
    EXPECT_EQ(m.action, Marker::ADD);
    EXPECT_EQ(m.color.a, 1.0);
  }
}

TEST(SimRos, named_robots_get_a_disc_a_heading_and_their_name_with_ids_by_index) {
  const sim::MultiRobotSimulator sim(twoRobots());
  const std::vector<Marker> trails = {makeTrail(0), makeTrail(1)};
  const visualization_msgs::MarkerArray array =
      toMarkers(worldMarkers(sim.world()), sim, trails, kStamp);
  for (const Marker& m : array.markers) {
    EXPECT_EQ(m.header.frame_id, "map") << m.ns;
    EXPECT_EQ(m.header.stamp, kStamp) << m.ns;
  }
  const std::vector<Marker> robots = inNamespace(array, "robot"),
                            headings = inNamespace(array, "heading"),
                            names = inNamespace(array, "names");
  ASSERT_EQ(robots.size(), 2u);
  ASSERT_EQ(headings.size(), 2u);
  ASSERT_EQ(names.size(), 2u);
  EXPECT_TRUE(inNamespace(array, "trail").empty()) << "a trail of fewer than two points";
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(robots[i].id, i);
    EXPECT_EQ(headings[i].id, i);
    EXPECT_EQ(names[i].id, i);
    EXPECT_EQ(names[i].type, Marker::TEXT_VIEW_FACING);
    EXPECT_DOUBLE_EQ(names[i].pose.position.x, robots[i].pose.position.x);
    EXPECT_LT(names[i].pose.position.y + 0.5 * names[i].scale.z,
              robots[i].pose.position.y - 0.5 * robots[i].scale.y)
        << "below its disc in the top-down view, clear of the state text on the robot";
    EXPECT_GT(names[i].pose.position.z, robots[i].scale.z);
    EXPECT_DOUBLE_EQ(robots[i].scale.x, 0.34);  // the disc's diameter
    EXPECT_DOUBLE_EQ(headings[i].scale.x, 0.17);
  }
  EXPECT_EQ(names[0].text, "robot1");
  EXPECT_EQ(names[1].text, "robot2");
  EXPECT_DOUBLE_EQ(robots[1].pose.position.x, 4.8);
  EXPECT_NEAR(headings[1].pose.orientation.z, 1.0, 1e-15) << "robot2 faces -x";
  EXPECT_GT(robots[0].color.b, robots[0].color.r) << "blue while the bumper is free";
}

TEST(SimRos, the_unnamed_robot_has_no_name_and_turns_red_while_its_bumper_is_pressed) {
  world::World world;
  world.robot().initial_pose = {0.17, 2.4, M_PI};  // touching the left wall
  sim::MultiRobotSimulator sim(world);
  sim.senseContact();
  ASSERT_TRUE(sim.bumper(0).pressed);
  const visualization_msgs::MarkerArray array = toMarkers({}, sim, {makeTrail(0)}, kStamp);
  EXPECT_TRUE(inNamespace(array, "names").empty());
  const std::vector<Marker> robot = inNamespace(array, "robot");
  ASSERT_EQ(robot.size(), 1u);
  EXPECT_GT(robot[0].color.r, robot[0].color.b);
}

TEST(SimRos, the_trail_grows_every_2_cm_and_keeps_the_newer_half_when_full) {
  Marker trail = makeTrail(3);
  EXPECT_EQ(trail.ns, "trail");
  EXPECT_EQ(trail.id, 3);
  EXPECT_EQ(trail.type, Marker::LINE_STRIP);
  extendTrail({1.0, 1.0, 0.0}, trail);
  extendTrail({1.01, 1.0, 0.0}, trail);  // 1 cm: not yet
  ASSERT_EQ(trail.points.size(), 1u);
  extendTrail({1.02, 1.0, 0.0}, trail);
  ASSERT_EQ(trail.points.size(), 2u);
  EXPECT_DOUBLE_EQ(trail.points[1].x, 1.02);

  const sim::MultiRobotSimulator sim{world::World{}};
  const visualization_msgs::MarkerArray array = toMarkers({}, sim, {trail}, kStamp);
  ASSERT_EQ(inNamespace(array, "trail").size(), 1u) << "two points: drawn";

  for (int i = 0; i < 6000; ++i) extendTrail({0.05 * (i % 100), 0.05 * (i / 100), 0.0}, trail);
  EXPECT_LE(trail.points.size(), 5000u);
  EXPECT_GE(trail.points.size(), 2500u);
  EXPECT_DOUBLE_EQ(trail.points.back().x, 0.05 * 99);
  EXPECT_DOUBLE_EQ(trail.points.back().y, 0.05 * 59);
}

}  // namespace
}  // namespace roomba_rrt::sim_node
