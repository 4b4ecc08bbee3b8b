// Conversions between the ROS interface of the rrt_planner node and the ROS-free planning
// library: a PlanPath request becomes a planning::Problem and planning::PlannerOptions (fields left
// at zero or empty take the node's defaults), and a planning::PlanResult becomes the response, a
// nav_msgs/Path and the rviz MarkerArray of the tree.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nav_msgs/Path.h>
#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include <roomba_rrt/PlanPath.h>
#include <roomba_rrt/planning/planner.h>

namespace roomba_rrt::planner_node {

/// What the node uses for every request field left at zero or empty (its private parameters).
struct NodeDefaults {
  planning::Point2 start{1, 1};  // the lab's case a
  planning::Point2 goal{9, 9};
  planning::Bounds bounds;           // the lab's [0, 10] x [0, 10]
  planning::PlannerOptions options;  // the lab's step, goal bias, iterations, tolerance, seed;
                                     // its max_planning_time is also the requests' limit
  double robot_radius = 0;           // m, when neither the request nor its scenario gives one
  double clearance = 0;              // m, likewise
  int max_iterations_cap = planning::kDefaultMaxIterationsCap;  // larger requests are rejected
  int ordinary_iterations = 20000;        // requests asking no more are served first (plan_slots.h)
  std::optional<planning::Problem> room;  // scenario "room": the simulator's world (~world_file)
  bool allow_unknown = false;  // ~allow_unknown: a map's unknown cells are free floor, not walls
  // Scenario "map" and make_plan until a map arrives on ~map_topic: ~world_file's map, if any.
  std::shared_ptr<const planning::Problem> world_map;
};

/// A request turned into the library's input, or the reason it cannot be.
struct ResolvedRequest {
  planning::Problem problem;
  planning::PlannerOptions options;
  std::string error;  // "" when the request is valid; otherwise names the offending field
};

/// The robot a map is planned for when neither the request nor ~robot_radius says: the Roomba.
constexpr double kMapRobotRadius = 0.17;
/// ~robot_radius when it is set (> 0), otherwise the Roomba's radius.
inline double mapRobotRadius(const NodeDefaults& d) {
  return d.robot_radius > 0 ? d.robot_radius : kMapRobotRadius;
}

/// Fills every field of `request` left at zero or empty from `defaults` (a named scenario fills
/// start, goal, obstacles and bounds; scenarios "room" and "map" fill all but start and goal,
/// which the request must give; "map" is `map`, nullptr when the node has none yet), then
/// validates the result. Never throws on bad input: the error message names the field
/// ("scenario: unknown 'z' ...", "step: must be in [...]", ...).
ResolvedRequest resolveRequest(const PlanPath::Request& request, const NodeDefaults& defaults,
                               const std::map<std::string, planning::Problem>& scenarios,
                               const planning::Problem* map = nullptr);

/// The path as a nav_msgs/Path (z = 0, identity orientations); empty when no path was found.
nav_msgs::Path toPathMessage(const std::vector<planning::Point2>& path, const std::string& frame_id,
                             const ros::Time& stamp);

/// Copies the plan's outcome into the service response (length +inf and an empty path on
/// failure).
void fillResponse(const planning::PlanResult& result, const std::string& frame_id,
                  const ros::Time& stamp, PlanPath::Response* response);

/// What the rviz picture shows.
struct MarkerScene {
  const planning::Problem* problem = nullptr;
  const planning::Tree* tree = nullptr;
  const std::vector<planning::Point2>* path = nullptr;  // may be empty or null (still growing)
  std::size_t max_tree_nodes = 200000;  // only nodes [0, max) and their edges are drawn
};

/// The markers of one plan, first a DELETEALL so that nothing of the previous plan stays:
/// namespace "bounds" (LINE_STRIP), "obstacles" (one CYLINDER each), "rectangles" (one CUBE
/// each), "start" and "goal"
/// (SPHEREs), "edges" (one LINE_LIST, two points per tree edge), "nodes" (POINTS) and "path"
/// (LINE_STRIP). Empty point sets are left out (rviz rejects them).
visualization_msgs::MarkerArray toMarkers(const MarkerScene& scene, const std::string& frame_id,
                                          const ros::Time& stamp);

}  // namespace roomba_rrt::planner_node
