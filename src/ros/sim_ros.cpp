#include "sim_ros.h"

#include <cmath>

#include "message_parts.h"

namespace roomba_rrt::sim_node {
namespace {

using visualization_msgs::Marker;

constexpr double kTrailSpacing = 0.02;      // m between trail points
constexpr std::size_t kTrailLength = 5000;  // points kept (100 m of path)
constexpr double kRobotHeight = 0.09, kFurnitureHeight = 0.4, kWallHeight = 0.3;
constexpr double kWallThickness = 0.05;

using nodes::color;
using nodes::yawToQuaternion;
using Rgba = std_msgs::ColorRGBA;
const Rgba kWallColour = color(0.55, 0.55, 0.55), kFurnitureColour = color(0.55, 0.35, 0.2),
           kTrailColour = color(0.1, 0.8, 0.3), kRobotColour = color(0.2, 0.6, 0.9),
           kPressedColour = color(0.9, 0.2, 0.2), kHeadingColour = color(1.0, 1.0, 1.0),
           kNameColour = color(0.9, 0.1, 0.7);  // names: readable on light and dark floor

/// A marker in the map frame; toMarkers() stamps the whole array.
Marker makeMarker(const std::string& ns, int id, int type, const Rgba& colour) {
  return nodes::makeMarker("map", ros::Time(), ns, id, type, colour);
}

/// A box marker over [x0, x1] × [y0, y1], `height` tall, standing on the floor.
Marker makeBox(const std::string& ns, int id, double x0, double y0, double x1, double y1,
               double height, const Rgba& colour) {
  auto m = makeMarker(ns, id, Marker::CUBE, colour);
  m.pose.position.x = 0.5 * (x0 + x1);
  m.pose.position.y = 0.5 * (y0 + y1);
  m.pose.position.z = 0.5 * height;
  m.scale.x = x1 - x0;
  m.scale.y = y1 - y0;
  m.scale.z = height;
  return m;
}

/// Robot i's disc, heading, trail (when it has two points) and, when named, its name.
void addRobotMarkers(const sim::MultiRobotSimulator& sim, std::size_t i, const Marker& trail,
                     visualization_msgs::MarkerArray& array) {
  const robot::Pose2D& pose = sim.pose(i);
  const double r = sim.spec(i).radius;
  const int id = static_cast<int>(i);
  auto robot = makeMarker("robot", id, Marker::CYLINDER,
                          sim.bumper(i).pressed ? kPressedColour : kRobotColour);
  robot.pose.position.x = pose.x;
  robot.pose.position.y = pose.y;
  robot.pose.position.z = 0.5 * kRobotHeight;
  robot.scale.x = robot.scale.y = 2 * r;
  robot.scale.z = kRobotHeight;
  array.markers.push_back(robot);

  auto heading = makeMarker("heading", id, Marker::ARROW, kHeadingColour);
  heading.pose.position.x = pose.x;
  heading.pose.position.y = pose.y;
  heading.pose.position.z = kRobotHeight + 0.01;
  heading.pose.orientation = yawToQuaternion(pose.theta);
  heading.scale.x = r;
  heading.scale.y = 0.04;
  heading.scale.z = 0.04;
  array.markers.push_back(heading);

  if (trail.points.size() >= 2) array.markers.push_back(trail);
  const std::string& name = sim.spec(i).name;
  if (!name.empty()) {
    auto label = makeMarker("names", id, Marker::TEXT_VIEW_FACING, kNameColour);
    label.text = name;
    // Below the disc as rviz's top-down view shows it: a behaviour node's state text sits on the
    // robot itself, and the two must not overlap.
    label.pose.position.x = pose.x;
    label.pose.position.y = pose.y - r - 0.12;
    label.pose.position.z = kRobotHeight + 0.15;
    label.scale.z = 0.15;  // text height, m
    array.markers.push_back(label);
  }
}

}  // namespace

RobotFrames robotFrames(const std::string& name) {
  const std::string prefix = name.empty() ? "" : name + "/";
  return {prefix, prefix + "odom", prefix + "base_link"};
}

nav_msgs::Odometry toOdometry(const robot::Pose2D& pose, const robot::Velocity& applied,
                              const RobotFrames& frames, const ros::Time& stamp) {
  nav_msgs::Odometry odom;
  odom.header.stamp = stamp;
  odom.header.frame_id = frames.odom;
  odom.child_frame_id = frames.base_link;
  odom.pose.pose.position.x = pose.x;
  odom.pose.pose.position.y = pose.y;
  odom.pose.pose.orientation = yawToQuaternion(pose.theta);
  odom.twist.twist.linear.x = applied.v;
  odom.twist.twist.angular.z = applied.w;
  return odom;
}

Bumper toBumper(const robot::BumperState& bumper, const RobotFrames& frames,
                const ros::Time& stamp) {
  Bumper msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frames.base_link;
  msg.pressed = bumper.pressed;
  msg.left = bumper.left;
  msg.right = bumper.right;
  return msg;
}

namespace {
/// parent → child at the planar `pose` of child in parent.
geometry_msgs::TransformStamped planarTransform(const std::string& parent, const std::string& child,
                                                const robot::Pose2D& pose, const ros::Time& stamp) {
  geometry_msgs::TransformStamped tf;
  tf.header.stamp = stamp;
  tf.header.frame_id = parent;
  tf.child_frame_id = child;
  tf.transform.translation.x = pose.x;
  tf.transform.translation.y = pose.y;
  tf.transform.rotation = yawToQuaternion(pose.theta);
  return tf;
}
}  // namespace

geometry_msgs::TransformStamped toOdomTransform(const robot::Pose2D& pose,
                                                const RobotFrames& frames, const ros::Time& stamp) {
  return planarTransform(frames.odom, frames.base_link, pose, stamp);
}

geometry_msgs::TransformStamped toSensorTransform(const sensors::RangeSensorSpec& sensor,
                                                  const RobotFrames& frames,
                                                  const ros::Time& stamp) {
  return planarTransform(frames.base_link, frames.prefix + sensor.frame, sensor.mount, stamp);
}

sensor_msgs::LaserScan toLaserScan(const sensors::RangeSensorSpec& sensor,
                                   const sensors::Scan& scan, const RobotFrames& frames,
                                   const ros::Time& stamp) {
  sensor_msgs::LaserScan msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frames.prefix + sensor.frame;
  msg.angle_min = static_cast<float>(sensor.angle_min);
  msg.angle_max = static_cast<float>(sensor.angle_max);
  msg.angle_increment = static_cast<float>(sensor.angleIncrement());
  msg.time_increment = 0;  // every ray at the same simulated instant
  msg.scan_time = static_cast<float>(1 / sensor.rate);
  msg.range_min = static_cast<float>(sensor.range_min);
  msg.range_max = static_cast<float>(sensor.range_max);
  msg.ranges = scan.ranges;
  return msg;
}

geometry_msgs::TransformStamped toMapTransform(const RobotFrames& frames, const ros::Time& stamp) {
  geometry_msgs::TransformStamped map_to_odom;
  map_to_odom.header.stamp = stamp;
  map_to_odom.header.frame_id = "map";
  map_to_odom.child_frame_id = frames.odom;
  map_to_odom.transform.rotation.w = 1.0;
  return map_to_odom;
}

std_msgs::Float32 toCoverageMessage(double coverage) {
  std_msgs::Float32 msg;
  msg.data = static_cast<float>(coverage);
  return msg;
}

nav_msgs::OccupancyGrid toCoverageMap(const sim::CoverageGrid& grid, const ros::Time& stamp) {
  nav_msgs::OccupancyGrid map;
  map.header.stamp = stamp;
  map.header.frame_id = "map";
  map.info.map_load_time = stamp;
  map.info.resolution = static_cast<float>(grid.cellSize());
  map.info.width = grid.columns();
  map.info.height = grid.rows();
  map.info.origin.position.x = grid.origin().x;
  map.info.origin.position.y = grid.origin().y;
  map.info.origin.orientation.w = 1.0;
  map.data.resize(static_cast<std::size_t>(grid.columns()) * grid.rows());
  for (int row = 0; row < grid.rows(); ++row) {
    for (int column = 0; column < grid.columns(); ++column) {
      const bool free = grid.isFree(column, row);
      map.data[row * grid.columns() + column] = !free ? 100 : grid.isSwept(column, row) ? 0 : -1;
    }
  }
  return map;
}

Marker makeTrail(std::size_t robot) {
  auto trail = makeMarker("trail", static_cast<int>(robot), Marker::LINE_STRIP, kTrailColour);
  trail.scale.x = 0.02;  // line width, m
  return trail;
}

void extendTrail(const robot::Pose2D& pose, Marker& trail) {
  std::vector<geometry_msgs::Point>& points = trail.points;
  if (!points.empty()) {
    const auto& last = points.back();
    if (std::hypot(pose.x - last.x, pose.y - last.y) < kTrailSpacing) return;
  }
  if (points.size() >= kTrailLength) {
    points.erase(points.begin(), points.begin() + kTrailLength / 2);
  }
  geometry_msgs::Point p;
  p.x = pose.x;
  p.y = pose.y;
  p.z = 0.01;
  points.push_back(p);
}

std::vector<Marker> worldMarkers(const world::World& w) {
  const double t = kWallThickness;
  const double x0 = w.room.origin.x, y0 = w.room.origin.y, x1 = x0 + w.room.width,
               y1 = y0 + w.room.height;
  std::vector<Marker> markers = {
      makeBox("walls", 0, x0 - t, y0 - t, x0, y1 + t, kWallHeight, kWallColour),
      makeBox("walls", 1, x1, y0 - t, x1 + t, y1 + t, kWallHeight, kWallColour),
      makeBox("walls", 2, x0, y0 - t, x1, y0, kWallHeight, kWallColour),
      makeBox("walls", 3, x0, y1, x1, y1 + t, kWallHeight, kWallColour),
  };
  int id = 0;
  for (const geometry::Circle& c : w.room.circles) {
    auto m = makeMarker("furniture", id++, Marker::CYLINDER, kFurnitureColour);
    m.pose.position.x = c.center.x;
    m.pose.position.y = c.center.y;
    m.pose.position.z = 0.5 * kFurnitureHeight;
    m.scale.x = m.scale.y = 2 * c.radius;
    m.scale.z = kFurnitureHeight;
    markers.push_back(m);
  }
  for (const geometry::Rectangle& b : w.room.rectangles) {
    markers.push_back(makeBox("furniture", id++, b.min_x, b.min_y, b.max_x, b.max_y,
                              kFurnitureHeight, kFurnitureColour));
  }
  return markers;
}

visualization_msgs::MarkerArray toMarkers(const std::vector<Marker>& world_markers,
                                          const sim::MultiRobotSimulator& sim,
                                          const std::vector<Marker>& trails,
                                          const ros::Time& stamp) {
  visualization_msgs::MarkerArray array;
  array.markers = world_markers;
  for (std::size_t i = 0; i < sim.size(); ++i) addRobotMarkers(sim, i, trails[i], array);
  for (auto& m : array.markers) m.header.stamp = stamp;
  return array;
}

}  // namespace roomba_rrt::sim_node
