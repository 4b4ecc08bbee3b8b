// coverage_planner: the coverage planner as a ROS service, as ROS users call a coverage planner
// (ipa_room_exploration's action, full_coverage_path_planner behind move_base): a start in, the
// path that sweeps the robot's disc over all the floor it can reach out.
//
// Serves ~plan_coverage (roomba_rrt/PlanCoverage) in ~world_file's world (the simulator's room,
// or a map_server map) or, with world "map", on the latest map on ~map_topic (/map: from
// roomba_sim, map_server, a SLAM node or a bag); after every plan publishes it on ~coverage_path
// (latched nav_msgs/Path) and its rows and transits on ~coverage_markers (latched MarkerArray)
// for rviz. Requests are answered one after the other: a room plans in milliseconds, a whole
// building's map in seconds. Parameters and examples: doc/nodes.md, "coverage_planner".
#include <algorithm>
#include <memory>
#include <string>

#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>

#include <roomba_rrt/PlanCoverage.h>
#include <roomba_rrt/util/require.h>
#include <roomba_rrt/world/world.h>
#include <roomba_rrt/world/world_file.h>

#include "../ros/coverage_ros.h"
#include "../ros/map_messages.h"
#include "../ros/master_watch.h"
#include "../ros/node_params.h"
#include "../ros/shutdown_grace.h"

namespace roomba_rrt::coverage_node {
namespace {

class CoveragePlannerNode {
 public:
  CoveragePlannerNode(ros::NodeHandle& pnh, nodes::NodeParams& params) {
    const std::string world_file =
        params.get<std::string>("world_file", nodes::packageConfigFile("roomba_world.yaml"));
    defaults_.room = std::make_shared<const world::World>(
        world::loadWorld(world_file, world::PoseSource::kElsewhere));
    map_robot_radius_ = params.get("robot_radius", defaults_.room->robot().radius);
    util::requireInRange("~robot_radius", map_robot_radius_, 1e-3,
                         world::WorldLimits::kMaxRobotRadius, "m");
    defaults_.clearance = params.get("clearance", defaults_.clearance);
    util::requireInRange("~clearance", defaults_.clearance, 0.0,
                         std::min(defaults_.room->robot().radius, map_robot_radius_), "m");
    defaults_.frame_id = params.get<std::string>("frame_id", "map");
    const std::string map_topic = params.get<std::string>("map_topic", "/map");
    path_pub_ = pnh.advertise<nav_msgs::Path>("coverage_path", 1, true);
    markers_pub_ = pnh.advertise<visualization_msgs::MarkerArray>("coverage_markers", 1, true);
    if (!map_topic.empty()) {
      map_sub_ = pnh.subscribe(map_topic, 1, &CoveragePlannerNode::onMap, this);
    }
    service_ = pnh.advertiseService("plan_coverage", &CoveragePlannerNode::plan, this);
    ROS_INFO("coverage_planner: ~plan_coverage in %s (world \"room\") and on %s (world \"map\")",
             world_file.c_str(), map_topic.empty() ? "no topic" : map_sub_.getTopic().c_str());
  }

 private:
  bool plan(PlanCoverage::Request& request, PlanCoverage::Response& response) {
    world::World planned_in;
    response = planCoverage(request, defaults_, ros::Time::now(), &planned_in);
    if (response.success) {
      path_pub_.publish(response.path);
      markers_pub_.publish(toMarkers(response, &planned_in));
      ROS_INFO("coverage_planner: %zu rows, %.1f m, %.1f m² reachable, in %.3f s",
               response.row_starts.size(), response.length, response.reachable_area,
               response.planning_time);
    } else {
      ROS_WARN_STREAM("coverage_planner: " << response.message);
    }
    return true;
  }

  // A map arrives (latched: at once, then at every change); a message that is not a map is
  // ignored, and requests keep the previous one.
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& message) {
    auto grid = std::make_shared<geometry::OccupancyGrid>();
    const std::string error = nodes::fromMapMessage(*message, grid.get());
    if (!error.empty()) {
      ROS_WARN_STREAM("coverage_planner: ignoring the map on " << map_sub_.getTopic() << ": "
                                                               << error);
      return;
    }
    defaults_.map =
        std::make_shared<const world::World>(world::mapWorld(std::move(grid), map_robot_radius_));
  }

  CoverageDefaults defaults_;
  double map_robot_radius_ = 0;
  ros::Publisher path_pub_;
  ros::Publisher markers_pub_;
  ros::Subscriber map_sub_;
  ros::ServiceServer service_;
};

}  // namespace
}  // namespace roomba_rrt::coverage_node

int main(int argc, char** argv) {
  if (roomba_rrt::nodes::printedHelp(argc, argv, "coverage_planner",
                                     "Plans coverage paths: ~plan_coverage "
                                     "(roomba_rrt/PlanCoverage), rows over all the floor the "
                                     "robot's disc can reach.")) {
    return 0;
  }
  ros::init(argc, argv, "coverage_planner");
  roomba_rrt::nodes::stopOnSigterm();
  ros::NodeHandle pnh("~");
  roomba_rrt::nodes::MasterWatch master_watch;
  try {
    roomba_rrt::nodes::NodeParams params(pnh);
    roomba_rrt::coverage_node::CoveragePlannerNode node(pnh, params);
    params.warnUnknown();
    // One thread serves requests and maps in turn; a plan (seconds for a whole building's map)
    // does not hold up Ctrl-C.
    roomba_rrt::nodes::spinWithShutdownGrace(1, master_watch, "coverage_planner");
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM("coverage_planner: " << e.what());
    return 1;
  }
  return master_watch.exitCode();
}
