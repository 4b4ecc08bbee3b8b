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
/// (BtTreeStatus, latched, on change), ~tree_markers (MarkerArray, latched, on change, at most
/// 10 Hz, in the odometry's frame beside the robot).
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

  bt::TreeMonitor monitor_;
  std::string tree_id_;
  std::unique_ptr<bt::groot2::Server> groot_;
  std::string snapshot_;  ///< the 'S' buffer, swapped with the server's
  ros::Publisher status_pub_, marker_pub_;
  bool markers_due_ = true;
  ros::WallTime last_markers_;
  std::vector<double> columns_;
};

/// Groot2's default port, as BehaviorTree.CPP's examples use it.
constexpr int kDefaultGrootPort = 1667;

}  // namespace roomba_rrt::nodes
