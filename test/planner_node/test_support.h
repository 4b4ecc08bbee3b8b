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

/// A request that names a lab scenario and leaves everything else to the node.
PlanPath::Request scenarioRequest(const std::string& name);

/// Calls ~plan_path (a fresh connection, as a separate client would); fails the current test
/// when the call itself fails twice (the node died or refused to answer).
PlanPath::Response callPlanPath(const PlanPath::Request& request);

/// The marker of namespace `ns` (id 0 unless given), or nullptr.
const visualization_msgs::Marker* findMarker(const visualization_msgs::MarkerArray& array,
                                             const std::string& ns, int id = 0);

/// Sum of the distances between consecutive poses.
double sumOfSegments(const nav_msgs::Path& path);

}  // namespace roomba_rrt::planner_node_test
