// Small message parts every node builds the same way: a colour, an rviz marker's common fields, a
// yaw as a quaternion. Header-only, so each node and its conversion tests just include it.
#pragma once

#include <cmath>
#include <string>

#include <geometry_msgs/Quaternion.h>
#include <ros/time.h>
#include <std_msgs/ColorRGBA.h>
#include <visualization_msgs/Marker.h>

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

/// A rotation by `yaw` about z.
inline geometry_msgs::Quaternion yawToQuaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(0.5 * yaw);
  q.w = std::cos(0.5 * yaw);
  return q;
}

}  // namespace roomba_rrt::nodes
