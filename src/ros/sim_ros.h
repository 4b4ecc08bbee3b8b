// Conversions between the ROS interface of the roomba_sim node and the ROS-free simulator: each
// robot's odometry, bumper, tf and scans, the static map → odom and base_link → sensor
// transforms, the coverage topics and map, and the rviz markers (walls, furniture, every robot with
// its heading, trail and name). Pure functions, unit-tested without a master
// (test/sim/sim_ros_test).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/MapMetaData.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/time.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Float32.h>
#include <visualization_msgs/MarkerArray.h>

#include <roomba_rrt/Bumper.h>

#include "roomba_rrt/robot/robot_state.h"
#include "roomba_rrt/sensors/scanner.h"
#include "roomba_rrt/sim/coverage_grid.h"
#include "roomba_rrt/sim/multi_robot_simulator.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::sim_node {

/// Where one robot's messages go: topics under `prefix`, tf frames `odom` → `base_link`.
struct RobotFrames {
  std::string prefix;     ///< "" for the unnamed robot, "<name>/" for a named one
  std::string odom;       ///< "odom" or "<name>/odom"
  std::string base_link;  ///< "base_link" or "<name>/base_link"
};

/// The frames of the robot called `name` ("" for the unnamed robot of today's world files).
RobotFrames robotFrames(const std::string& name);

/// The robot's pose in its odom frame (which is the room's: odometry is perfect, so every
/// covariance is zero) and the command it applied, as velocities in base_link.
nav_msgs::Odometry toOdometry(const robot::Pose2D& pose, const robot::Velocity& applied,
                              const RobotFrames& frames, const ros::Time& stamp);

/// The bumper, in base_link.
Bumper toBumper(const robot::BumperState& bumper, const RobotFrames& frames,
                const ros::Time& stamp);

/// odom → base_link at the robot's pose.
geometry_msgs::TransformStamped toOdomTransform(const robot::Pose2D& pose,
                                                const RobotFrames& frames, const ros::Time& stamp);

/// base_link → the sensor's frame (prefixed as the robot's frames) at its mounting pose: static.
geometry_msgs::TransformStamped toSensorTransform(const sensors::RangeSensorSpec& sensor,
                                                  const RobotFrames& frames,
                                                  const ros::Time& stamp);

/// A scan as sensor_msgs/LaserScan in the sensor's frame: its angles, range limits, scan_time
/// 1 / rate, time_increment 0 (every ray at the simulated instant `stamp`), the ranges with
/// REP 117's ±inf, no intensities.
sensor_msgs::LaserScan toLaserScan(const sensors::RangeSensorSpec& sensor,
                                   const sensors::Scan& scan, const RobotFrames& frames,
                                   const ros::Time& stamp);

/// map → odom, the identity (published once, latched, by the static broadcaster).
geometry_msgs::TransformStamped toMapTransform(const RobotFrames& frames, const ros::Time& stamp);

/// The swept fraction of the free floor, in [0, 1].
std_msgs::Float32 toCoverageMessage(double coverage);

/// The grid in frame "map", one cell per coverage cell with its origin at the room's: swept
/// floor 0 (white in rviz's "map" colours), floor not yet swept −1 (unknown), furniture 100
/// (black). Row-major from the room's lower-left corner, as OccupancyGrid wants.
nav_msgs::OccupancyGrid toCoverageMap(const sim::CoverageGrid& grid, const ros::Time& stamp);

/// Robot `robot`'s trail: namespace "trail", a green LINE_STRIP 2 cm wide, no points yet.
visualization_msgs::Marker makeTrail(std::size_t robot);

/// Adds the pose to the trail when it is 2 cm or more from the last point; a full trail (5000
/// points, 100 m of path) first drops its older half.
void extendTrail(const robot::Pose2D& pose, visualization_msgs::Marker& trail);

/// Walls (namespace "walls", ids 0–3: left, right, bottom, top) and furniture (namespace
/// "furniture", circles then rectangles from id 0) as boxes and cylinders standing on the floor
/// of frame "map". They never change: build them once.
std::vector<visualization_msgs::Marker> worldMarkers(const world::World& world);

/// What rviz shows, every marker in frame "map" stamped `stamp`: `world_markers`, then for each
/// robot i (id i in each namespace) its disc (namespace "robot", blue, red while its bumper is
/// pressed), its heading ("heading", an arrow as long as the radius), its trail once it has two
/// points (trails[i]) and, for a named robot, its name above it ("names", TEXT_VIEW_FACING).
visualization_msgs::MarkerArray toMarkers(
    const std::vector<visualization_msgs::Marker>& world_markers,
    const sim::MultiRobotSimulator& sim, const std::vector<visualization_msgs::Marker>& trails,
    const ros::Time& stamp);

}  // namespace roomba_rrt::sim_node
