// What the rrt_planner rostests share: calling ~plan_path, building requests, finding markers.
// test_support.cpp also holds main(): ros::init, wait for the service, run the tests.
#pragma once

#include <string>

#include <visualization_msgs/MarkerArray.h>

#include <roomba_rrt/PlanPath.h>

namespace roomba_rrt::planner_node_test {

inline constexpr char kService[] = "/rrt_planner/plan_path";
inline constexpr char kTreeTopic[] = "/rrt_planner/tree";
inline constexpr char kPathTopic[] = "/rrt_planner/path";

geometry_msgs::Point point(double x, double y);
CircleObstacle circle(double x, double y, double radius);

/// A request that names a lab scenario and leaves everything else to the node.
PlanPath::Request scenarioRequest(const std::string& name);

/// A goal that no tree can reach: the corner pocket behind a disc that cuts the corner of the
/// bounds off (the disc reaches past both walls, so no step of 0.2 can jump into the pocket).
/// With a large iteration budget this plan runs long and then fails.
PlanPath::Request unreachableGoal(int max_iterations);

/// Calls ~plan_path (a fresh connection, as a separate client would); fails the current test
/// when the call itself fails twice (the node died or refused to answer).
PlanPath::Response callPlanPath(const PlanPath::Request& request);

/// The marker of namespace `ns` (id 0 unless given), or nullptr.
const visualization_msgs::Marker* findMarker(const visualization_msgs::MarkerArray& array,
                                             const std::string& ns, int id = 0);

/// Sum of the distances between consecutive poses.
double sumOfSegments(const nav_msgs::Path& path);

}  // namespace roomba_rrt::planner_node_test
