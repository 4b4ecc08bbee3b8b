#include "planner_ros.h"

#include <cmath>
#include <sstream>

#include "message_parts.h"

namespace roomba_rrt::planner_node {
namespace {

using nodes::color;
using nodes::deleteAllMarker;
using nodes::flatFurniture;
using nodes::makeMarker;
using nodes::outline;
using planning::Point2;
using visualization_msgs::Marker;

planning::Point2 toPoint2(const geometry_msgs::Point& p) { return {p.x, p.y}; }

geometry_msgs::Point toPointMsg(const Point2& p, double z = 0.0) {
  geometry_msgs::Point msg;
  msg.x = p.x;
  msg.y = p.y;
  msg.z = z;
  return msg;
}

// The request's rule: a field left at zero takes the node's value. NaN is not zero, so it reaches
// planning::validate, which names the field.
template <typename T>
T orDefault(T value, T fallback) {
  return value == T{} ? fallback : value;
}

bool isUnset(const geometry_msgs::Point& p) { return p.x == 0 && p.y == 0; }  // z is ignored

bool boundsGiven(const PlanPath::Request& r) {
  return r.x_min != 0 || r.x_max != 0 || r.y_min != 0 || r.y_max != 0;
}

// The first request field that states geometry explicitly, or "" when none does.
std::string explicitGeometryField(const PlanPath::Request& r) {
  if (!isUnset(r.start)) return "start";
  if (!isUnset(r.goal)) return "goal";
  if (!r.obstacles.empty()) return "obstacles";
  if (!r.rectangles.empty()) return "rectangles";
  if (boundsGiven(r)) return "x_min/x_max/y_min/y_max";
  return "";
}

// z is not part of the planning problem, but a NaN there is still bad input.
std::string nonFiniteHeight(const PlanPath::Request& r) {
  if (!std::isfinite(r.start.z)) return "start.z: must be finite";
  if (!std::isfinite(r.goal.z)) return "goal.z: must be finite";
  for (std::size_t i = 0; i < r.obstacles.size(); ++i) {
    if (!std::isfinite(r.obstacles[i].center.z)) {
      return "obstacles[" + std::to_string(i) + "].center.z: must be finite";
    }
  }
  return "";
}

std::string knownScenarios(const std::map<std::string, planning::Problem>& scenarios,
                           const NodeDefaults& defaults) {
  std::string names;
  for (const auto& entry : scenarios) names += (names.empty() ? "" : ", ") + entry.first;
  if (defaults.room) names += names.empty() ? "room" : ", room";
  names += names.empty() ? "map" : ", map";
  return names;
}

// Scenarios "room" and "map": a world the node holds (the simulator's world file, the map),
// with the request's start and goal (both required).
std::string resolveWorld(const PlanPath::Request& r, const planning::Problem& world,
                         planning::Problem* problem) {
  for (const auto& [field, given] :
       {std::pair<const char*, bool>{"start", !isUnset(r.start)}, {"goal", !isUnset(r.goal)}}) {
    if (!given) {
      return std::string(field) + ": required for scenario '" + r.scenario +
             "' (where the robot is)";
    }
  }
  if (!r.obstacles.empty() || !r.rectangles.empty() || boundsGiven(r)) {
    return "scenario: '" + r.scenario +
           "' cannot be combined with explicit obstacles, rectangles or bounds (" +
           (r.scenario == "map" ? "the map gives them)" : "the world file gives them)");
  }
  *problem = world;
  problem->start = toPoint2(r.start);
  problem->goal = toPoint2(r.goal);
  return "";
}

// Start, goal, obstacles and bounds: from the named scenario, or from the request with the
// node's defaults for what it leaves out. Returns "" or an error naming the field.
std::string resolveGeometry(const PlanPath::Request& r, const NodeDefaults& defaults,
                            const std::map<std::string, planning::Problem>& scenarios,
                            const planning::Problem* map, planning::Problem* problem) {
  if (r.scenario == "room" && defaults.room) return resolveWorld(r, *defaults.room, problem);
  if (r.scenario == "map") {
    if (!map) {
      return "scenario: 'map': no map yet (none received on ~map_topic, and ~world_file is not a "
             "map)";
    }
    const std::string error = resolveWorld(r, *map, problem);
    problem->robot_radius = mapRobotRadius(defaults);
    return error;
  }
  if (!r.scenario.empty()) {
    const auto found = scenarios.find(r.scenario);
    if (found == scenarios.end()) {
      return "scenario: unknown '" + r.scenario +
             "' (known: " + knownScenarios(scenarios, defaults) + ")";
    }
    const std::string field = explicitGeometryField(r);
    if (!field.empty()) {
      return "scenario: cannot be combined with explicit " + field +
             " (a scenario fills start, goal, obstacles and bounds)";
    }
    *problem = found->second;
    return "";
  }
  problem->start = isUnset(r.start) ? defaults.start : toPoint2(r.start);
  problem->goal = isUnset(r.goal) ? defaults.goal : toPoint2(r.goal);
  problem->obstacles.clear();
  for (const auto& obstacle : r.obstacles) {
    problem->obstacles.push_back({toPoint2(obstacle.center), obstacle.radius});
  }
  problem->rectangles.clear();
  for (const auto& box : r.rectangles) {
    problem->rectangles.push_back({box.min_x, box.min_y, box.max_x, box.max_y});
  }
  problem->bounds =
      boundsGiven(r) ? planning::Bounds{r.x_min, r.x_max, r.y_min, r.y_max} : defaults.bounds;
  return "";
}

// The robot's size: the request's where given, otherwise the scenario's (the room's robot),
// otherwise the node's (~robot_radius, ~clearance; 0 by default: the lab's point).
void resolveRobot(const PlanPath::Request& r, const NodeDefaults& defaults,
                  planning::Problem* problem) {
  problem->robot_radius =
      orDefault(r.robot_radius, orDefault(problem->robot_radius, defaults.robot_radius));
  problem->clearance = orDefault(r.clearance, orDefault(problem->clearance, defaults.clearance));
}

// Planner options: the node's, overridden by every request field that is set.
std::string resolveOptions(const PlanPath::Request& r, const NodeDefaults& defaults,
                           planning::PlannerOptions* options) {
  *options = defaults.options;
  options->step = orDefault(r.step, options->step);
  options->goal_bias = orDefault(r.goal_bias, options->goal_bias);
  options->max_iterations = orDefault(r.max_iterations, options->max_iterations);
  options->goal_tolerance = orDefault(r.goal_tolerance, options->goal_tolerance);
  options->seed = orDefault(r.seed, options->seed);
  options->smooth = options->smooth || r.smooth;
  options->max_planning_time = orDefault(r.max_planning_time, options->max_planning_time);
  if (!r.algorithm.empty()) {
    const auto algorithm = planning::parseAlgorithm(r.algorithm);
    if (!algorithm) {
      return "algorithm: unknown '" + r.algorithm +
             "' (expected rrt, rrt_connect, rrt_star or region_astar)";
    }
    options->algorithm = *algorithm;
  }
  if (!r.collision_check.empty()) {
    const auto collision = planning::parseCollisionCheck(r.collision_check);
    if (!collision) {
      return "collision_check: unknown '" + r.collision_check + "' (expected points or segments)";
    }
    options->collision = *collision;
  }
  // The lab's stream wherever the lab's MATLAB code could pose the same problem (its scenarios,
  // explicit discs and bounds), so answers stay comparable with MATLAB's and with earlier
  // versions; the fast one in the room and on maps, which the lab never had.
  options->random_stream = r.scenario == "room" || r.scenario == "map"
                               ? planning::RandomStream::kFast
                               : planning::RandomStream::kMatlab;
  if (!r.random_stream.empty()) {
    const auto stream = planning::parseRandomStream(r.random_stream);
    if (!stream) {
      return "random_stream: unknown '" + r.random_stream + "' (expected matlab or fast)";
    }
    options->random_stream = *stream;
  }
  return "";
}

// The node's ~max_planning_time is also the most a request may ask for (0: no limit).
std::string checkPlanningTimeLimit(const PlanPath::Request& r, const NodeDefaults& defaults) {
  const double limit = defaults.options.max_planning_time;
  if (limit <= 0 || r.max_planning_time <= limit) return "";
  std::ostringstream out;
  out << "max_planning_time: " << r.max_planning_time << " s is above the node's limit of " << limit
      << " s (~max_planning_time)";
  return out.str();
}

Marker sphereMarker(const Point2& at, const Marker& base) {
  Marker m = base;
  m.pose.position = toPointMsg(at);
  m.scale.x = m.scale.y = m.scale.z = 0.3;  // diameter
  return m;
}

// Edges (two points each) and nodes of the first `max_nodes` nodes of the tree.
void addTree(const planning::Tree& tree, std::size_t max_nodes, Marker* edges, Marker* nodes) {
  const std::size_t n = std::min(tree.nodes.size(), max_nodes);
  edges->points.reserve(2 * n);
  nodes->points.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    nodes->points.push_back(toPointMsg(tree.nodes[i]));
    const int parent = i < tree.parent.size() ? tree.parent[i] : -1;
    if (parent < 0 || static_cast<std::size_t>(parent) >= n) continue;
    edges->points.push_back(toPointMsg(tree.nodes[parent]));
    edges->points.push_back(toPointMsg(tree.nodes[i]));
  }
}

}  // namespace

ResolvedRequest resolveRequest(const PlanPath::Request& request, const NodeDefaults& defaults,
                               const std::map<std::string, planning::Problem>& scenarios,
                               const planning::Problem* map) {
  ResolvedRequest resolved;
  resolved.error = nonFiniteHeight(request);
  if (resolved.error.empty()) {
    resolved.error = resolveGeometry(request, defaults, scenarios, map, &resolved.problem);
    resolveRobot(request, defaults, &resolved.problem);
  }
  if (resolved.error.empty()) resolved.error = resolveOptions(request, defaults, &resolved.options);
  if (resolved.error.empty()) {
    try {
      planning::validate(resolved.problem, resolved.options, defaults.max_iterations_cap);
    } catch (const util::InvalidInput& invalid) {
      resolved.error = invalid.what();
    }
  }
  if (resolved.error.empty()) resolved.error = checkPlanningTimeLimit(request, defaults);
  return resolved;
}

nav_msgs::Path toPathMessage(const std::vector<Point2>& path, const std::string& frame_id,
                             const ros::Time& stamp) {
  nav_msgs::Path msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp = stamp;
  msg.poses.reserve(path.size());
  for (const Point2& p : path) {
    geometry_msgs::PoseStamped pose;
    pose.header = msg.header;
    pose.pose.position = toPointMsg(p);
    pose.pose.orientation.w = 1.0;
    msg.poses.push_back(pose);
  }
  return msg;
}

void fillResponse(const planning::PlanResult& result, const std::string& frame_id,
                  const ros::Time& stamp, PlanPath::Response* response) {
  response->success = result.success;
  response->message = result.message;
  response->path = toPathMessage(result.path, frame_id, stamp);
  response->length = result.length;
  response->iterations = result.iterations;
  response->tree_size = static_cast<int>(result.tree.nodes.size());
  response->planning_time = result.planning_time;
}

visualization_msgs::MarkerArray toMarkers(const MarkerScene& scene, const std::string& frame_id,
                                          const ros::Time& stamp) {
  visualization_msgs::MarkerArray array;
  array.markers.push_back(deleteAllMarker(frame_id, stamp));

  const planning::Problem& problem = *scene.problem;
  const planning::Bounds& b = problem.bounds;
  array.markers.push_back(outline(
      {b.x_min, b.y_min, b.x_max, b.y_max},
      makeMarker(frame_id, stamp, "bounds", 0, Marker::LINE_STRIP, color(0.1f, 0.1f, 0.1f)), 0.04));
  // Flat, just below the tree.
  for (std::size_t i = 0; i < problem.obstacles.size(); ++i) {
    array.markers.push_back(flatFurniture(
        problem.obstacles[i], makeMarker(frame_id, stamp, "obstacles", static_cast<int>(i),
                                         Marker::CYLINDER, color(0.35f, 0.35f, 0.35f))));
  }
  for (std::size_t i = 0; i < problem.rectangles.size(); ++i) {
    array.markers.push_back(flatFurniture(
        problem.rectangles[i], makeMarker(frame_id, stamp, "rectangles", static_cast<int>(i),
                                          Marker::CUBE, color(0.35f, 0.35f, 0.35f))));
  }
  array.markers.push_back(sphereMarker(
      problem.start,
      makeMarker(frame_id, stamp, "start", 0, Marker::SPHERE, color(0.1f, 0.7f, 0.1f))));
  array.markers.push_back(sphereMarker(
      problem.goal,
      makeMarker(frame_id, stamp, "goal", 0, Marker::SPHERE, color(0.9f, 0.5f, 0.0f))));

  Marker edges =
      makeMarker(frame_id, stamp, "edges", 0, Marker::LINE_LIST, color(0.2f, 0.4f, 1.0f, 0.8f));
  edges.scale.x = 0.015;
  Marker nodes = makeMarker(frame_id, stamp, "nodes", 0, Marker::POINTS, color(0.0f, 0.1f, 0.6f));
  nodes.scale.x = nodes.scale.y = 0.04;
  if (scene.tree != nullptr) addTree(*scene.tree, scene.max_tree_nodes, &edges, &nodes);
  if (!edges.points.empty()) array.markers.push_back(std::move(edges));
  if (!nodes.points.empty()) array.markers.push_back(std::move(nodes));

  if (scene.path != nullptr && scene.path->size() >= 2) {
    Marker path =
        makeMarker(frame_id, stamp, "path", 0, Marker::LINE_STRIP, color(0.9f, 0.1f, 0.1f));
    path.scale.x = 0.06;
    for (const Point2& p : *scene.path) path.points.push_back(toPointMsg(p, 0.01));
    array.markers.push_back(std::move(path));
  }
  return array;
}

}  // namespace roomba_rrt::planner_node
