// The ROS adapter shared by roomba_fsm and roomba_bt: parameters in, /bumper and /odom in,
// /cmd_vel, ~state and ~state_marker out, one behaviour tick per timer event.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <ros/ros.h>

#include "node_params.h"
#include "roomba_rrt/behavior/roomba_behavior.h"

namespace roomba_rrt::nodes {

/// The node's one /cmd_vel publisher. The node publishes each tick's command through it; a
/// behaviour that must act between timer events (roomba_bt's navigation: a goal arrived, plan and
/// move now; a goal was refused or canceled, stop now) publishes through the same one.
class CommandOutput {
 public:
  explicit CommandOutput(ros::NodeHandle& nh);
  /// Publishes `cmd`; a component that is not finite goes out as 0.
  void publish(const robot::Velocity& cmd);
  void stop() { publish({}); }

 private:
  ros::Publisher pub_;
};

/// Makes the behaviour from the parameters; `node_params` reads node-specific ones (roomba_bt's
/// ~tree_file); `output` is the node's /cmd_vel (it outlives the behaviour). May throw
/// std::exception: the node then exits with its message.
using BehaviorMaker = std::function<std::unique_ptr<behavior::RoombaBehavior>(
    NodeParams& node_params, const behavior::RoombaParams& params, std::uint32_t seed,
    CommandOutput& output)>;

/// Runs a behaviour node until shutdown and returns the process exit code (non-zero when the
/// parameters or the behaviour cannot be loaded).
///
/// A behaviour with a behavior tree (RoombaBehavior::behaviorTree()) is watched (tree_watch.h:
/// ~groot_port, ~tree_status, ~tree_markers); `tree_nodes_model` is the <TreeNodesModel> Groot2
/// gets with the tree, `tree_file` the file whose main tree runs (its ID names the tree).
///
/// Parameters (read strictly, written back while the node runs, unknown ones warned about:
/// NodeParams): ~config_file (default $(rospack find roomba_rrt)/config/roomba_behavior.yaml),
/// ~rate (Hz, default: the file's rate, 60), ~seed (default 1), ~bumper_timeout (s of ROS time
/// without /bumper before the node stops the robot, default 0.5) and ~base_frame.
int runBehaviorNode(int argc, char** argv, const std::string& node_name,
                    const BehaviorMaker& make_behavior, const std::string& tree_nodes_model = "");

/// One of the robot's frames by default: `frame` (base_link), or <ns>/`frame` when the node runs
/// in a namespace (roomba_sim's frames for a named robot), so that
/// `rosrun roomba_rrt roomba_fsm __ns:=robot1` needs no frame parameter. Call after ros::init.
std::string robotFrame(const std::string& frame);

}  // namespace roomba_rrt::nodes
