// roomba_bt's windows into its tree: Groot2 live monitoring on ~groot_port, ~tree_status, and
// ~tree_markers (the tree drawn beside the robot in rviz, each node coloured by its status).
#pragma once

#include <memory>
#include <string>

#include <ros/ros.h>

#include "node_params.h"
#include "roomba_rrt/bt/groot2_server.h"
#include "roomba_rrt/bt/tree.h"
#include "roomba_rrt/bt/tree_monitor.h"

namespace roomba_rrt::nodes {

/// Watches one tree after each tick. Parameters: ~groot_port (default 1667; 0: no Groot2 server;
/// a port that cannot be bound is logged and the tree runs without it). Topics: ~tree_status
/// (BtTreeStatus, latched, on change), ~tree_markers (MarkerArray, latched: the tree drawn in the
/// odometry's frame beside the robot, on the side towards where the robot started and near it, each
/// node a box coloured by its status, again when a status changed or the robot moved 0.3 m, at most
/// 10 Hz).
class TreeWatch {
 public:
  /// `tree_id` names the tree for Groot2; `model_xml` is the <TreeNodesModel> document Groot2
  /// draws the nodes with.
  TreeWatch(ros::NodeHandle& pnh, NodeParams& params, bt::Tree& tree, const std::string& tree_id,
            const std::string& model_xml);

  /// After a tick (or a group of catch-up ticks): publishes what changed. (x, y) in `frame` is the
  /// robot, where the tree is drawn.
  void afterTick(double x, double y, const std::string& frame);

 private:
  void publishStatus();
  void publishMarkers(double x, double y, const std::string& frame);

  bt::Tree& tree_;
  bt::TreeMonitor monitor_;
  std::string tree_id_;
  std::unique_ptr<bt::groot2::Server> groot_;
  std::string snapshot_;  ///< the 'S' buffer, swapped with the server's
  ros::Publisher status_pub_, marker_pub_;
  bool markers_due_ = true;
  double anchor_x_ = 0, anchor_y_ = 0;  ///< where the robot was when the tree was last drawn
  double home_x_ = 0, home_y_ = 0;      ///< where the robot was first drawn (the tree leans there)
  bool have_home_ = false;
  ros::WallTime last_markers_;
  ros::WallTime last_heartbeat_check_;
  bool groot_connected_ = false;
  std::vector<double> columns_;
};

/// Groot2's default port, as BehaviorTree.CPP's examples use it.
constexpr int kDefaultGrootPort = 1667;

}  // namespace roomba_rrt::nodes
