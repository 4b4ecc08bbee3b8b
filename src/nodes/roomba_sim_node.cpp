// roomba_sim: the simulated Roombas as a ROS node — a thin adapter around
// roomba_rrt::sim::MultiRobotSimulator.
//
// One unnamed robot (today's world files): subscribes /cmd_vel; publishes /odom, /bumper, tf
// odom→base_link (+ static map→odom, the identity: odometry is perfect and in room coordinates).
// Named robots (`robots:` in the world file): the same per robot under its name — /<name>/cmd_vel,
// /<name>/odom, /<name>/bumper, tf <name>/odom→<name>/base_link, static map→<name>/odom,
// ~<name>/coverage — each with its own command timeout. Every range sensor of the world file
// (the LDS preset when it names none): sensor_msgs/LaserScan on /[<name>/]<sensor name> at its
// rate in simulated time, static tf [<name>/]base_link→[<name>/]<frame>. Always one /clock (when
// /use_sim_time is true), ~markers (every robot, with its name), ~coverage and ~coverage_map (the
// union); service ~reset. Parameters: doc/nodes.md, "roomba_sim".
#include <cstdio>
#include <stdexcept>
#include <string>

#include <roomba_rrt/RoombaSimConfig.h>
#include <ros/ros.h>

#include "../ros/master_watch.h"
#include "../ros/node_params.h"
#include "../ros/reconfigure.h"
#include "../ros/roomba_sim.h"
#include "../ros/shutdown_grace.h"

int main(int argc, char** argv) {
  if (roomba_rrt::nodes::printedHelp(argc, argv, "roomba_sim",
                                     "Simulates the Roomba(s) of ~world_file: cmd_vel in; odom, "
                                     "bumper, tf, /map and markers out.")) {
    return 0;
  }
  ros::init(argc, argv, "roomba_sim");
  roomba_rrt::nodes::stopOnSigterm();
  ros::NodeHandle pnh("~");
  const bool use_sim_time = ros::param::param("/use_sim_time", false);
  roomba_rrt::nodes::NodeParams params(pnh);
  roomba_rrt::world::WorldFile file;
  try {
    file = roomba_rrt::sim_node::loadWorldParameters(params);
  } catch (const std::invalid_argument& e) {
    ROS_FATAL("roomba_sim: invalid world: %s", e.what());
    return 1;
  }
  const roomba_rrt::world::World& world = file.world;
  if (!use_sim_time && file.simulator.real_time_factor != 1.0) {
    ROS_WARN("roomba_sim: ~real_time_factor %g needs /use_sim_time true; running in real time",
             file.simulator.real_time_factor);
  }
  roomba_rrt::nodes::MasterWatch master_watch;
  // ~publish_map false: the robot does not get the true map (it maps the world: roomba_mapper).
  const bool publish_map = params.get<bool>("publish_map", true);
  if (!publish_map && world.room.map) {
    ROS_INFO("roomba_sim: ~publish_map false: the world's map is not published on /map");
  }
  roomba_rrt::sim_node::RoombaSim node(world, file.simulator, use_sim_time, publish_map);
  for (const std::string& name : roomba_rrt::nodes::parameterNames<roomba_rrt::RoombaSimConfig>()) {
    params.expect(name);  // dynamic_reconfigure's (cfg/RoombaSim.cfg)
  }
  params.warnUnknown();
  // One robot: where it starts (the file's pose, or --pose / ~initial_pose's).
  char start[96] = "";
  if (!world.namedRobots()) {
    const roomba_rrt::robot::Pose2D& p = world.robot().initial_pose;
    std::snprintf(start, sizeof start, " at (%g, %g) heading %g rad", p.x, p.y, p.theta);
  }
  ROS_INFO("roomba_sim: %.1f x %.1f m room, %zu pieces of furniture, %zu robot%s%s, %s",
           world.room.width, world.room.height,
           world.room.circles.size() + world.room.rectangles.size(), world.robots.size(),
           world.robots.size() > 1 ? "s" : "", start,
           use_sim_time ? "publishing /clock" : "wall-clock time");
  node.run();
  return master_watch.exitCode();
}
