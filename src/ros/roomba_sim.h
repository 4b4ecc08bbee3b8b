// The roomba_sim node's adapter around sim::MultiRobotSimulator: the world from ~world_file and
// its private parameters, every robot's topics and tf, the sensors' scans, /clock, the markers,
// ~reset and dynamic_reconfigure (src/ros/roomba_sim.cpp). src/nodes/roomba_sim_node.cpp is its
// main.
#pragma once

#include <memory>

#include "node_params.h"
#include "roomba_rrt/world/world.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::sim_node {

/// Reads the world file, then lets every scalar be overridden by a private parameter of the same
/// path (~real_time_factor, ~initial_pose/x, ~robot/radius, ...). Throws std::invalid_argument
/// naming the bad parameter.
world::WorldFile loadWorldParameters(nodes::NodeParams& params);

class RoombaSimNode;

/// The node for `world`: its publishers, subscribers and services exist from construction;
/// run() steps the simulation until ROS shuts down.
class RoombaSim {
 public:
  /// `publish_map` false: the world's map stays the simulator's (~publish_map: the robot maps
  /// the world itself, roomba_mapper publishes /map).
  RoombaSim(const world::World& world, const world::SimulatorSettings& settings, bool use_sim_time,
            bool publish_map = true);
  ~RoombaSim();
  void run();

 private:
  std::unique_ptr<RoombaSimNode> node_;
};

}  // namespace roomba_rrt::sim_node
