#include "tree_watch.h"

#include <roomba_rrt/BtTreeStatus.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <cmath>

#include "message_parts.h"

namespace roomba_rrt::nodes {
namespace {

constexpr double kColumnWidth = 0.9;  ///< m between neighbouring leaves (at most)
constexpr double kTreeWidth = 4.0;    ///< m: wider trees get narrower columns
/// m: how far from where the robot started the tree may reach (the lab's room is 6.4 x 4.8 m
/// and the robot starts in its middle), so that it stays in the room's view.
constexpr double kReachX = 3.0, kReachY = 2.2;
constexpr double kCharWidth = 0.45;    ///< a character's width in rviz's text, per text height
constexpr double kRowHeight = 0.4;     ///< m between a parent and its children
constexpr double kOffset = 0.6;        ///< m from the robot to the tree
constexpr double kFollow = 0.3;        ///< m the robot moves before the tree follows it
constexpr double kMarkerPeriod = 0.1;  ///< s: ~tree_markers at most 10 Hz

std_msgs::ColorRGBA statusColor(bt::MonitorStatus status) {
  switch (status) {
    case bt::MonitorStatus::kRunning:
      return color(1.0f, 0.65f, 0.0f);  // orange, as Groot2
    case bt::MonitorStatus::kSuccess:
      return color(0.1f, 0.8f, 0.1f);
    case bt::MonitorStatus::kFailure:
      return color(0.9f, 0.1f, 0.1f);
    case bt::MonitorStatus::kIdleFromRunning:
      return color(0.55f, 0.45f, 0.25f);  // faded, as Groot2 fades a node gone idle
    case bt::MonitorStatus::kIdleFromSuccess:
      return color(0.3f, 0.5f, 0.3f);
    case bt::MonitorStatus::kIdleFromFailure:
      return color(0.55f, 0.3f, 0.3f);
    case bt::MonitorStatus::kSkipped:
      return color(0.3f, 0.5f, 0.9f);  // blue
    case bt::MonitorStatus::kIdleFromSkipped:
    case bt::MonitorStatus::kIdle:
      break;
  }
  return color(0.5f, 0.5f, 0.5f);
}

}  // namespace

TreeWatch::TreeWatch(ros::NodeHandle& pnh, NodeParams& params, bt::Tree& tree,
                     const std::string& tree_id, const std::string& model_xml)
    : tree_(tree), monitor_(tree.root()), tree_id_(tree_id), columns_(bt::treeColumns(monitor_)) {
  const int port = params.get("groot_port", kDefaultGrootPort);
  if (port < 0 || port > 65534) {
    throw std::invalid_argument("~groot_port must be 0 (off) or a TCP port in 1..65534, got " +
                                std::to_string(port));
  }
  bt::groot2::statusSnapshot(monitor_, snapshot_);
  if (port > 0) {
    try {
      groot_ = std::make_unique<bt::groot2::Server>(
          port, bt::treeXmlWithUids(monitor_, tree_id, model_xml), snapshot_, tree_id);
      ROS_INFO("Groot2: monitor tree '%s' on port %d (Groot2: Monitor, Connect to localhost:%d)",
               tree_id.c_str(), port, port);
    } catch (const std::runtime_error& e) {
      ROS_ERROR("%s; the tree runs without Groot2 monitoring (set ~groot_port)", e.what());
    }
  }
  status_pub_ = pnh.advertise<BtTreeStatus>("tree_status", 1, /*latch=*/true);
  marker_pub_ = pnh.advertise<visualization_msgs::MarkerArray>("tree_markers", 1, /*latch=*/true);
  publishStatus();
}

void TreeWatch::afterTick(double x, double y, const std::string& frame) {
  if (groot_ && groot_->blackboardWanted()) {
    groot_->provideBlackboard(bt::groot2::snapshotBlackboard(tree_.blackboard()));
  }
  if (monitor_.update()) {
    if (groot_) {
      bt::groot2::statusSnapshot(monitor_, snapshot_);
      groot_->publishStatus(snapshot_);
    }
    publishStatus();
    markers_due_ = true;
  }
  if (std::hypot(x - anchor_x_, y - anchor_y_) > kFollow) markers_due_ = true;
  const ros::WallTime now = ros::WallTime::now();
  if (markers_due_ && !frame.empty() && (now - last_markers_).toSec() >= kMarkerPeriod) {
    publishMarkers(x, y, frame);
    anchor_x_ = x;
    anchor_y_ = y;
    markers_due_ = false;
    last_markers_ = now;
  }
  // BehaviorTree.CPP's heartbeat: a client that sent nothing for 5 s has left.
  if (groot_ && (now - last_heartbeat_check_).toSec() >= 1.0) {
    last_heartbeat_check_ = now;
    if (groot_->clientConnected() != groot_connected_) {
      groot_connected_ = !groot_connected_;
      ROS_INFO("Groot2: %s (port %d)",
               groot_connected_ ? "a client is monitoring the tree" : "the client left",
               groot_->port());
    }
  }
}

void TreeWatch::publishStatus() {
  BtTreeStatus msg;
  msg.header.stamp = ros::Time::now();
  msg.tree_id = tree_id_;
  const auto& nodes = monitor_.nodes();
  msg.nodes.resize(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    BtNodeStatus& n = msg.nodes[i];
    n.uid = nodes[i].uid;
    n.parent_uid = nodes[i].parent < 0 ? 0 : nodes[nodes[i].parent].uid;
    n.path = nodes[i].path;
    n.name = nodes[i].name;
    n.type = nodes[i].type;
    n.status = static_cast<std::uint8_t>(monitor_.statuses()[i]);
  }
  status_pub_.publish(msg);
}

void TreeWatch::publishMarkers(double x, double y, const std::string& frame) {
  const auto& nodes = monitor_.nodes();
  double leaves = 1;
  int depth = 0;
  for (double c : columns_) leaves = std::max(leaves, c + 1);
  for (const bt::MonitoredNode& n : nodes) depth = std::max(depth, n.depth);
  const double width = std::min(kColumnWidth, kTreeWidth / leaves);
  // The tree goes on the side of the robot towards where it started (the room's middle in the
  // lab), so that it stays in view when the robot is near a wall.
  if (!have_home_) {
    home_x_ = x;
    home_y_ = y;
    have_home_ = true;
  }
  const double tree_width = leaves * width, tree_height = (depth + 1) * kRowHeight;
  const auto keepNearHome = [](double low, double size, double home, double reach) {
    const double half = std::max(size / 2, reach);
    return std::clamp(low, home - half, home + half - size);
  };
  const double left = keepNearHome(x > home_x_ ? x - kOffset - tree_width : x + kOffset, tree_width,
                                   home_x_, kReachX);
  const double top =
      keepNearHome(
          (y > home_y_ ? y + kRowHeight / 2 : y + (depth + 0.5) * kRowHeight) - tree_height,
          tree_height, home_y_, kReachY) +
      tree_height;
  const auto place = [&](std::size_t i) {
    geometry_msgs::Point p;
    p.x = left + width / 2 + columns_[i] * width;
    p.y = top - nodes[i].depth * kRowHeight;
    p.z = 0.05;
    return p;
  };
  visualization_msgs::MarkerArray array;
  visualization_msgs::Marker edges =
      makeMarker(frame, ros::Time::now(), "tree_edges", 0, visualization_msgs::Marker::LINE_LIST,
                 color(0.8f, 0.8f, 0.8f));
  edges.scale.x = 0.01;
  visualization_msgs::Marker boxes =
      makeMarker(frame, ros::Time::now(), "tree_nodes", 0, visualization_msgs::Marker::CUBE_LIST,
                 color(1.0f, 1.0f, 1.0f));
  boxes.scale.x = width * 0.92;
  boxes.scale.y = kRowHeight * 0.45;
  boxes.scale.z = 0.02;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const geometry_msgs::Point p = place(i);
    boxes.points.push_back(p);
    boxes.colors.push_back(statusColor(monitor_.statuses()[i]));
    if (nodes[i].parent >= 0) {
      edges.points.push_back(place(static_cast<std::size_t>(nodes[i].parent)));
      edges.points.push_back(p);
    }
    visualization_msgs::Marker label =
        makeMarker(frame, ros::Time::now(), "tree_labels", static_cast<int>(i),
                   visualization_msgs::Marker::TEXT_VIEW_FACING, color(1.0f, 1.0f, 1.0f));
    label.pose.position = p;
    label.pose.position.z = 0.1;
    label.scale.z = std::min(0.14, width / 4);
    // A name wider than its box is cut short, so that neighbours do not overlap.
    const auto fits = static_cast<std::size_t>(width * 0.92 / (kCharWidth * label.scale.z));
    label.text = nodes[i].name.size() <= fits || fits < 2 ? nodes[i].name
                                                          : nodes[i].name.substr(0, fits - 1) + ".";
    array.markers.push_back(label);
  }
  array.markers.push_back(edges);
  array.markers.push_back(boxes);
  marker_pub_.publish(array);
}

}  // namespace roomba_rrt::nodes
