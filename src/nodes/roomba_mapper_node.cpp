// roomba_mapper: a map the robot builds, as a ROS node — a thin adapter around
// roomba_rrt::mapping::OccupancyMapper, with gmapping's interface.
//
// Subscribes `scan` (sensor_msgs/LaserScan) and `bumper` (roomba_rrt/Bumper), with the pose of
// the scan's frame and of ~base_frame from tf in ~odom_frame; publishes the map latched on `map`
// and `map_metadata` (frame ~map_frame) after the first scan and then every
// ~map_update_interval when it changed; serves ~dynamic_map (nav_msgs/GetMap). Parameters:
// doc/nodes.md, "roomba_mapper".
#include <stdexcept>

#include <ros/ros.h>

#include "../ros/master_watch.h"
#include "../ros/node_params.h"
#include "../ros/roomba_mapper.h"
#include "../ros/shutdown_grace.h"

int main(int argc, char** argv) {
  if (roomba_rrt::nodes::printedHelp(argc, argv, "roomba_mapper",
                                     "Builds an occupancy grid from scan, bumper and tf; "
                                     "publishes it on /map, /map_metadata and ~dynamic_map.")) {
    return 0;
  }
  ros::init(argc, argv, "roomba_mapper");
  roomba_rrt::nodes::stopOnSigterm();
  ros::NodeHandle pnh("~");
  roomba_rrt::nodes::NodeParams params(pnh);
  roomba_rrt::mapper_node::MapperSettings settings;
  try {
    settings = roomba_rrt::mapper_node::readSettings(params);
  } catch (const std::invalid_argument& e) {
    ROS_FATAL("roomba_mapper: %s", e.what());
    return 1;
  }
  params.warnUnknown();
  roomba_rrt::nodes::MasterWatch master_watch;
  roomba_rrt::mapper_node::RoombaMapper node(settings);
  ros::spin();
  return master_watch.exitCode();
}
