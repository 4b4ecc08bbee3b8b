// roomba_bt with a navigation tree (config/roomba_nav_tree.xml): NavBt behind move_base's ROS
// interface. A behaviour for runBehaviorNode (behavior_node.h), which keeps ticking it on its
// timer with /bumper; this adds the goal topic, the move_base action, the robot's pose from tf2,
// ~plan, and the planner client.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <ros/ros.h>

#include "behavior_node.h"
#include "node_params.h"
#include "roomba_rrt/behavior/roomba_behavior.h"

namespace roomba_rrt::nav_node {

/// The navigation behaviour of roomba_bt, set up from the private parameters (see doc/nodes.md,
/// "roomba_bt with a navigation tree"): ~world_file, ~planner ("service" or "in_process"),
/// ~plan_path_service, ~clearance, ~global_frame, ~robot_frame (default base_link, or
/// <ns>/base_link in a namespace: a named robot of roomba_sim), ~max_linear_speed,
/// ~max_angular_speed, ~xy_tolerance, ~yaw_tolerance. std::invalid_argument naming the
/// parameter when one is invalid. Its commands between timer events (a new goal, a goal refused or
/// canceled) go out through the node's `output`.
std::unique_ptr<behavior::RoombaBehavior> makeNavBehavior(nodes::NodeParams& node_params,
                                                          const behavior::RoombaParams& params,
                                                          std::uint32_t seed,
                                                          const std::string& tree_file,
                                                          nodes::CommandOutput& output);

}  // namespace roomba_rrt::nav_node
