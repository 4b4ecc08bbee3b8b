// The roomba_mapper node's adapter around mapping::OccupancyMapper, as gmapping is used: scans
// (sensor_msgs/LaserScan on `scan`) and the bumper (roomba_rrt/Bumper on `bumper`) in, with the
// robot's pose from tf (~odom_frame → the scan's frame, ~base_frame); the map out, latched, on
// `map` and `map_metadata` in ~map_frame, every ~map_update_interval, and on the ~dynamic_map
// service (nav_msgs/GetMap). The pure conversions are here to be tested without a master
// (src/ros/roomba_mapper.cpp; scans and tf: scan_input.h); src/nodes/roomba_mapper_node.cpp is its
// main.
#pragma once

#include <memory>
#include <string>

#include "node_params.h"
#include "roomba_rrt/mapping/occupancy_mapper.h"
#include "roomba_rrt/robot/robot_state.h"

namespace roomba_rrt::mapper_node {

/// The node's parameters (doc/nodes.md, "roomba_mapper").
struct MapperSettings {
  mapping::MapperOptions options;
  std::string map_frame = "map";         ///< the published map's frame
  std::string odom_frame = "odom";       ///< the frame the map is drawn in (= map: no SLAM)
  std::string base_frame = "base_link";  ///< the robot's frame (the bumper's pose)
  double map_update_interval = 5.0;      ///< s (simulated) between two publications of `map`
  /// s (by the stamps of newer messages) a scan or bump waits for tf to give its pose
  double transform_timeout = 0.2;
  int throttle_scans = 1;      ///< use one scan in this many
  double robot_radius = 0.17;  ///< m, where the bumper's switches are
};

/// Reads the private parameters (gmapping's names: ~delta, ~xmin, ..., ~maxUrange, ~occ_thresh,
/// ~map_update_interval, ~throttle_scans, the frames). Throws std::invalid_argument naming the
/// parameter ("~delta: must be in [0.001, 10] m, got 0").
MapperSettings readSettings(nodes::NodeParams& params);

class RoombaMapperNode;

/// The node: its subscriptions, publishers and service exist from construction; ros::spin()
/// runs it.
class RoombaMapper {
 public:
  explicit RoombaMapper(const MapperSettings& settings);
  ~RoombaMapper();

 private:
  std::unique_ptr<RoombaMapperNode> node_;
};

}  // namespace roomba_rrt::mapper_node
