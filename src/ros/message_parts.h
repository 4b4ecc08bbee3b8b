// Small message parts every node builds the same way: a colour, an rviz marker's common fields,
// furniture and walls drawn flat, a yaw as a quaternion and back. Header-only, so each node and
// its conversion tests just include it.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include <geometry_msgs/Quaternion.h>
#include <ros/time.h>
#include <std_msgs/ColorRGBA.h>
#include <visualization_msgs/Marker.h>

#include "roomba_rrt/geometry/geometry.h"

namespace roomba_rrt::nodes {

/// An RGBA colour, opaque unless `a` says otherwise.
inline std_msgs::ColorRGBA color(float r, float g, float b, float a = 1.0f) {
  std_msgs::ColorRGBA c;
  c.r = r;
  c.g = g;
  c.b = b;
  c.a = a;
  return c;
}

/// A marker to ADD with its frame, stamp, namespace, id, type and colour set and an identity
/// orientation (rviz rejects an all-zero quaternion); position and scale are the caller's.
inline visualization_msgs::Marker makeMarker(const std::string& frame_id, const ros::Time& stamp,
                                             const std::string& ns, int id, int type,
                                             const std_msgs::ColorRGBA& rgba) {
  visualization_msgs::Marker m;
  m.header.frame_id = frame_id;
  m.header.stamp = stamp;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.color = rgba;
  return m;
}

/// The marker that clears every marker its display shows: the first of a MarkerArray that
/// replaces what was drawn before.
inline visualization_msgs::Marker deleteAllMarker(const std::string& frame_id,
                                                  const ros::Time& stamp) {
  visualization_msgs::Marker m;
  m.header.frame_id = frame_id;
  m.header.stamp = stamp;
  m.action = visualization_msgs::Marker::DELETEALL;
  return m;
}

/// A piece of furniture drawn flat just below what is planned round it: `base` (a CYLINDER with
/// its frame, namespace, id and colour) as a 10 cm thick disc of the circle, 5 cm down.
inline visualization_msgs::Marker flatFurniture(const geometry::Circle& circle,
                                                visualization_msgs::Marker base) {
  base.pose.position.x = circle.center.x;
  base.pose.position.y = circle.center.y;
  base.pose.position.z = -0.05;
  base.scale.x = base.scale.y = 2.0 * circle.radius;
  base.scale.z = 0.1;
  return base;
}

/// The same for a rectangle: `base` a CUBE, drawn as a 10 cm thick box of it, 5 cm down.
inline visualization_msgs::Marker flatFurniture(const geometry::Rectangle& box,
                                                visualization_msgs::Marker base) {
  base.pose.position.x = 0.5 * (box.min_x + box.max_x);
  base.pose.position.y = 0.5 * (box.min_y + box.max_y);
  base.pose.position.z = -0.05;
  base.scale.x = box.max_x - box.min_x;
  base.scale.y = box.max_y - box.min_y;
  base.scale.z = 0.1;
  return base;
}

/// The rectangle's outline (walls, sampling bounds): `base` a LINE_STRIP of `width` through its
/// four corners and back to the first.
inline visualization_msgs::Marker outline(const geometry::Rectangle& box,
                                          visualization_msgs::Marker base, double width) {
  base.scale.x = width;
  const double corners[][2] = {{box.min_x, box.min_y},
                               {box.max_x, box.min_y},
                               {box.max_x, box.max_y},
                               {box.min_x, box.max_y},
                               {box.min_x, box.min_y}};
  for (const auto& corner : corners) {
    geometry_msgs::Point p;
    p.x = corner[0];
    p.y = corner[1];
    base.points.push_back(p);
  }
  return base;
}

/// A frame id as tf2 takes it: ROS 1 tools read "/map" as "map", tf2 refuses a leading '/' and
/// warns about it on every lookup (unthrottled, some ten lines per request), so the slashes are
/// dropped before comparing frames or asking tf2.
inline std::string tfFrameId(const std::string& frame_id) {
  const std::size_t first = frame_id.find_first_not_of('/');
  return first == std::string::npos ? std::string() : frame_id.substr(first);
}

/// A rotation by `yaw` about z.
inline geometry_msgs::Quaternion yawToQuaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(0.5 * yaw);
  q.w = std::cos(0.5 * yaw);
  return q;
}

/// The heading (yaw about z, ZYX convention) of any finite quaternion, unit or not: it is scaled
/// by its largest component first, so 1e300 in every component gives a heading, not NaN from
/// inf - inf. 0 for the all-zero quaternion of a message that left the orientation unset; NaN if
/// a component is not finite.
inline double quaternionToYaw(const geometry_msgs::Quaternion& q) {
  const double largest = std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z), std::abs(q.w)});
  if (largest == 0) return 0;
  const double x = q.x / largest, y = q.y / largest, z = q.z / largest, w = q.w / largest;
  return std::atan2(2 * (w * z + x * y), w * w + x * x - y * y - z * z);
}

}  // namespace roomba_rrt::nodes
