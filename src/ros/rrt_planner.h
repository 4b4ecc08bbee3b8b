// The rrt_planner node's adapter: the planning library behind ~plan_path and ~make_plan, its
// markers, its map subscription and its dynamic_reconfigure server (src/ros/rrt_planner.cpp).
// src/nodes/rrt_planner_node.cpp is its main.
#pragma once

#include <memory>

#include <ros/ros.h>

#include "node_params.h"

namespace roomba_rrt::planner_node {

class RrtPlannerNode;

/// Serves the node in `pnh` with the parameters read from `params` until it is destroyed;
/// throws std::exception naming a bad parameter.
class RrtPlanner {
 public:
  RrtPlanner(ros::NodeHandle& pnh, nodes::NodeParams& params);
  ~RrtPlanner();
  /// How many plans run at once (~threads, at least 2).
  int planThreads() const;
  /// How many threads its callbacks need (planThreads() and more: see rrt_planner.cpp).
  int callbackThreads() const;

 private:
  std::unique_ptr<RrtPlannerNode> node_;
};

}  // namespace roomba_rrt::planner_node
