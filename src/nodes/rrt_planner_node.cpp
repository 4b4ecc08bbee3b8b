// rrt_planner: the RRT planning library as a ROS service.
//
// Serves ~plan_path (roomba_rrt/PlanPath), with the lab's scenarios, scenario "room" (the
// simulator's ~world_file) and scenario "map" (the latest map on ~map_topic, /map), and
// ~make_plan (nav_msgs/GetPlan, move_base's) on that map, a pose every map cell as navfn answers
// (both wait up to 5 s for the first map); after every plan publishes the tree, obstacles, start,
// goal, bounds and path on ~tree (latched visualization_msgs/MarkerArray) and the path on ~path
// (latched nav_msgs/Path). With ~animate the growing tree is published while
// planning. Requests are served by several threads, so a long plan does not hold up other clients;
// when all ~threads are taken an ordinary request preempts the oldest long plan and a long request
// is answered "busy" at once (plan_slots.h), and every plan stops after ~max_planning_time seconds
// (or less, if the request asks). Parameters and examples: doc/nodes.md, "rrt_planner", and
// doc/planning.md.
#include <exception>

#include <ros/ros.h>

#include "../ros/master_watch.h"
#include "../ros/node_params.h"
#include "../ros/rrt_planner.h"
#include "../ros/shutdown_grace.h"

int main(int argc, char** argv) {
  if (roomba_rrt::nodes::printedHelp(argc, argv, "rrt_planner",
                                     "Plans paths with RRT, RRT* and RRT-Connect: ~plan_path "
                                     "(roomba_rrt/PlanPath), ~make_plan (nav_msgs/GetPlan).")) {
    return 0;
  }
  ros::init(argc, argv, "rrt_planner");
  roomba_rrt::nodes::stopOnSigterm();
  ros::NodeHandle pnh("~");
  roomba_rrt::nodes::MasterWatch master_watch;
  try {
    roomba_rrt::nodes::NodeParams params(pnh);
    roomba_rrt::planner_node::RrtPlanner node(pnh, params);
    params.warnUnknown();
    // Several threads: each request is planned in its own callback, so a long plan leaves the
    // other threads free to accept and answer further requests; more threads than plans may run
    // at once, so that an ordinary request never waits in the callback queue behind long plans
    // (RrtPlanner::callbackThreads()). A plan (up to minutes long) does not hold up Ctrl-C.
    roomba_rrt::nodes::spinWithShutdownGrace(node.callbackThreads(), master_watch, "rrt_planner");
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM("rrt_planner: " << e.what());
    return 1;
  }
  return master_watch.exitCode();
}
