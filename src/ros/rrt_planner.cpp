// The rrt_planner node (rrt_planner.h): its parameters, services, topics and reconfigure server.
#include "rrt_planner.h"

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nav_msgs/GetPlan.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <ros/callback_queue.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include <roomba_rrt/PlanPath.h>
#include <roomba_rrt/RrtPlannerConfig.h>
#include <roomba_rrt/planning/densify.h>
#include <roomba_rrt/planning/grid_regions.h>
#include <roomba_rrt/planning/planner.h>
#include <roomba_rrt/util/require.h>
#include <roomba_rrt/world_planning/room_problem.h>
#include "roomba_rrt/world/world_file.h"

#include "make_plan_ros.h"
#include "map_messages.h"
#include "master_watch.h"
#include "message_parts.h"
#include "node_params.h"
#include "plan_slots.h"
#include "planner_ros.h"
#include "reconfigure.h"
#include "shutdown_grace.h"

namespace roomba_rrt::planner_node {
namespace {

planning::Point2 pointParam(nodes::NodeParams& pnh, const std::string& name,
                            const planning::Point2& fallback) {
  const auto xy = pnh.get(name, std::vector<double>{fallback.x, fallback.y});
  if (xy.size() != 2) throw std::invalid_argument("~" + name + ": expected [x, y]");
  return {xy[0], xy[1]};
}

// A choice given by name ("rrt", "segments", ...), parsed by the library.
template <typename Enum>
Enum enumParam(nodes::NodeParams& pnh, const std::string& name, Enum fallback,
               std::optional<Enum> (*parse)(const std::string&)) {
  const auto text = pnh.get<std::string>(name, planning::toString(fallback));
  const std::optional<Enum> value = parse(text);
  if (!value) throw std::invalid_argument("~" + name + ": unknown '" + text + "'");
  return *value;
}

// The defaults must make a valid request on their own (the empty request plans with them):
// util::InvalidInput naming the field otherwise.
void validateDefaults(const NodeDefaults& d) {
  planning::Problem problem;
  problem.start = d.start;
  problem.goal = d.goal;
  problem.bounds = d.bounds;
  problem.robot_radius = d.robot_radius;
  problem.clearance = d.clearance;
  if (!(d.options.max_planning_time > 0)) {  // the upper end is validate()'s
    throw util::InvalidInput("max_planning_time", "must be > 0 s (every plan has a time limit)");
  }
  // region_astar plans on a map only: whether a request has one is checked per request.
  planning::PlannerOptions options = d.options;
  if (options.algorithm == planning::Algorithm::kRegionAStar) {
    options.algorithm = planning::Algorithm::kRrt;
  }
  planning::validate(problem, options, d.max_iterations_cap);
}

// Seconds a plan may take unless ~max_planning_time says otherwise.
constexpr double kDefaultMaxPlanningTime = 5.0;

// The node's defaults for every request field left at zero or empty. The code's fallbacks are
// the library's (the lab's) values; config/rrt_planner.yaml spells them out.
NodeDefaults loadDefaults(nodes::NodeParams& pnh) {
  NodeDefaults d;
  d.start = pointParam(pnh, "start", d.start);
  d.goal = pointParam(pnh, "goal", d.goal);
  d.bounds.x_min = pnh.get("x_min", d.bounds.x_min);
  d.bounds.x_max = pnh.get("x_max", d.bounds.x_max);
  d.bounds.y_min = pnh.get("y_min", d.bounds.y_min);
  d.bounds.y_max = pnh.get("y_max", d.bounds.y_max);
  planning::PlannerOptions& o = d.options;
  o.step = pnh.get("step", o.step);
  o.goal_bias = pnh.get("goal_bias", o.goal_bias);
  o.max_iterations = pnh.get("max_iterations", o.max_iterations);
  o.goal_tolerance = pnh.get("goal_tolerance", o.goal_tolerance);
  const int seed = pnh.get("seed", static_cast<int>(o.seed));
  if (seed < 0) throw std::invalid_argument("~seed: must be >= 0");
  o.seed = static_cast<std::uint32_t>(seed);
  o.smooth = pnh.get("smooth", o.smooth);
  o.algorithm = enumParam(pnh, "algorithm", o.algorithm, planning::parseAlgorithm);
  o.collision = enumParam(pnh, "collision_check", o.collision, planning::parseCollisionCheck);
  o.nearest = enumParam(pnh, "nearest", o.nearest, planning::parseNearestSearch);
  d.robot_radius = pnh.get("robot_radius", d.robot_radius);
  d.clearance = pnh.get("clearance", d.clearance);
  o.max_planning_time = pnh.get("max_planning_time", kDefaultMaxPlanningTime);
  d.max_iterations_cap = pnh.get("max_iterations_cap", d.max_iterations_cap);
  d.ordinary_iterations = pnh.get("ordinary_iterations", d.ordinary_iterations);
  if (d.ordinary_iterations < 1) throw std::invalid_argument("~ordinary_iterations: must be >= 1");
  // planning::plan() validates again with the library's own cap, so it bounds ours.
  if (d.max_iterations_cap < 1 || d.max_iterations_cap > planning::kDefaultMaxIterationsCap) {
    throw std::invalid_argument("~max_iterations_cap: must be in [1, " +
                                std::to_string(planning::kDefaultMaxIterationsCap) + "]");
  }
  try {
    validateDefaults(d);
  } catch (const util::InvalidInput& invalid) {
    throw std::invalid_argument("parameter ~" + std::string(invalid.what()));
  }
  // Scenario "room": the simulator's world file (its room, furniture and robot radius).
  const std::string world_file =
      pnh.get<std::string>("world_file", nodes::packageConfigFile("roomba_world.yaml"));
  d.allow_unknown = pnh.get("allow_unknown", d.allow_unknown);
  if (!world_file.empty()) {
    // Throws with the reason. Its initial pose may be a wall (a map's (0, 0)): requests give
    // their own start.
    const world::World world = world::loadWorld(world_file, world::PoseSource::kElsewhere);
    d.room = world_planning::roomProblem(world);
    if (world.room.map) {
      // Scenario "map": the map alone. Its unknown cells are walls in the room too, so the room's
      // inflated map serves unless ~allow_unknown asks for another.
      planning::Problem map;
      map.bounds = d.room->bounds;
      map.map = d.allow_unknown ? planning::mapProblem(world.room.map, true).map : d.room->map;
      map.regions = std::make_shared<const planning::GridRegionsCache>(map.map);
      d.world_map = std::make_shared<const planning::Problem>(std::move(map));
    }
  }
  return d;
}

// The widest ~plan_resolution, m: a pose every few metres is what densifying is there to avoid.
constexpr double kMaxPlanResolution = 10.0;

// How long make_plan (and plan_path's scenario "map") wait for the first map on ~map_topic.
constexpr std::chrono::seconds kFirstMapWait{5};

// ~threads: plans at once, in [1, kMaxThreads]; 1 is raised to 2.
int threadsParam(nodes::NodeParams& pnh) {
  constexpr int kMaxThreads = 64;
  const int threads = pnh.get("threads", 4);
  util::requireInRange("~threads", threads, 1, kMaxThreads);
  return std::max(2, threads);
}

}  // namespace

class RrtPlannerNode {
 public:
  RrtPlannerNode(ros::NodeHandle& pnh, nodes::NodeParams& params)
      : defaults_(std::make_shared<const NodeDefaults>(loadDefaults(params))),
        slots_(threadsParam(params)) {
    const std::string scenarios_file =
        params.get<std::string>("scenarios_file", nodes::packageConfigFile("rrt_scenarios.yaml"));
    scenarios_ = planning::loadScenarios(scenarios_file);  // throws with the reason
    frame_id_ = params.get<std::string>("frame_id", "map");
    max_marker_nodes_ = params.get("max_marker_nodes", 200000);
    animate_ = params.get("animate", false);
    animate_every_ = params.get("animate_every", 10);
    const double animate_rate = params.get("animate_rate", 20.0);
    // Documented ranges (doc/nodes.md): outside them the node stops at start naming the parameter.
    util::requireInRange("~max_marker_nodes", max_marker_nodes_, 0,
                         planning::kDefaultMaxIterationsCap);
    if (animate_every_ < 1) throw std::invalid_argument("~animate_every: must be >= 1");
    util::requireInRange("~animate_rate", animate_rate, 0.1, 1000, "Hz");
    // make_plan's spacing of poses: 0 for the map's resolution (navfn's one pose per cell).
    plan_resolution_ = params.get("plan_resolution", 0.0);
    util::requireInRange("~plan_resolution", plan_resolution_, 0, kMaxPlanResolution, "m");
    animate_period_ = ros::WallDuration(1.0 / animate_rate);

    tree_pub_ = pnh.advertise<visualization_msgs::MarkerArray>("tree", 10, /*latch=*/true);
    path_pub_ = pnh.advertise<nav_msgs::Path>("path", 1, /*latch=*/true);
    service_ = pnh.advertiseService("plan_path", &RrtPlannerNode::planPath, this);
    make_plan_service_ = pnh.advertiseService("make_plan", &RrtPlannerNode::makePlan, this);
    // The map: the latest on ~map_topic (map_server's, roomba_sim's, a bag's), "" for none.
    // Maps arrive on their own thread: requests waiting for the first map (waitForMap) hold the
    // service threads, never the map.
    const std::string map_topic = params.get<std::string>("map_topic", "/map");
    if (!map_topic.empty()) {
      ros::NodeHandle nh;
      nh.setCallbackQueue(&map_queue_);
      map_sub_ = nh.subscribe(map_topic, 1, &RrtPlannerNode::onMap, this);
      map_spinner_.start();
    }
    ROS_INFO_STREAM("rrt_planner: serving "
                    << service_.getService() << " with " << scenarios_.size() << " scenarios from "
                    << scenarios_file << (defaults_->room ? ", scenario room" : "")
                    << ", and scenario map and " << make_plan_service_.getService()
                    << (map_topic.empty() ? "" : " on the map from " + map_sub_.getTopic())
                    << (defaults_->world_map ? " (until then the world file's map)" : ""));
    startReconfigure(pnh);
  }

  /// How many plans run at once (~threads, at least 2).
  int planThreads() const { return slots_.capacity(); }
  /// Threads serving callbacks: one per plan, one per preempted plan still winding down (it
  /// stops within about a millisecond of its own CPU time, which on a busy machine can be much
  /// longer in wall time), and two for the answers that take no thread (busy, rejected).
  int callbackThreads() const { return 2 * planThreads() + 2; }

 private:
  // Called concurrently by the spinner's threads: touches only const members and thread-safe
  // publishers, so one long plan never holds up another request.
  bool planPath(PlanPath::Request& request, PlanPath::Response& response) {
    response.success = false;
    response.length = std::numeric_limits<double>::infinity();
    response.path.header.frame_id = frame_id_;
    const std::shared_ptr<const planning::Problem> map =
        request.scenario == "map" ? waitForMap("plan_path") : currentMap();
    const ResolvedRequest resolved = resolveRequest(request, *defaults(), scenarios_, map.get());
    if (!resolved.error.empty()) {
      response.message = resolved.error;
      ROS_WARN_STREAM("plan_path: rejected: " << resolved.error);
      return true;  // the client gets success: false and the message
    }
    // Ordinary requests (no more iterations than ~ordinary_iterations) are served first: see
    // plan_slots.h.
    const bool ordinary = resolved.options.max_iterations <= defaults()->ordinary_iterations;
    planning::PlanResult result;
    bool preempted = false;
    {
      // The thread is held for the plan alone, given back before the answer is built and the
      // markers (up to ~max_marker_nodes) are drawn and published.
      const PlanSlots::Lease slot =
          ordinary ? slots_.acquireOrdinary(deadlineOf(resolved.options)) : slots_.acquireLong();
      if (!slot) {
        response.message =
            ordinary ? "busy: all " + std::to_string(slots_.capacity()) +
                           " planning threads (~threads) ran ordinary plans for this request's "
                           "whole time budget; call again"
                     : "busy: all " + std::to_string(slots_.capacity()) +
                           " planning threads (~threads) are in use and this request asks more "
                           "than ~ordinary_iterations (" +
                           std::to_string(defaults()->ordinary_iterations) +
                           "): long plans only use free threads; call again later";
        ROS_WARN_STREAM("plan_path: " << response.message);
        return true;
      }
      try {
        result = plan(resolved, slot);
      } catch (const std::exception& e) {
        return planError(e, &response);
      }
      preempted = slot.stopRequested();
    }
    try {
      const ros::Time stamp = ros::Time::now();
      fillResponse(result, frame_id_, stamp, &response);
      if (preempted && !result.success) {
        response.message =
            "preempted: every planning thread was taken and this plan, asking more than "
            "~ordinary_iterations, had run the longest of those: it gave its thread to an "
            "ordinary request; call again";
        ROS_WARN_STREAM("plan_path: " << response.message);
        // Its tree and empty path would replace the plan that preempted it on ~tree and ~path.
        // Drawing it costs too: a latched topic's message is serialized under roscpp's one lock
        // for every publication, so up to ~max_marker_nodes markers of an abandoned plan would
        // hold up the ordinary request's own answer.
        return true;
      }
      tree_pub_.publish(markers(resolved.problem, result.tree, &result.path, stamp));
      path_pub_.publish(response.path);
      ROS_DEBUG_STREAM("plan_path: " << (result.success ? "found" : "no path") << ", length "
                                     << result.length << ", " << result.iterations
                                     << " iterations, " << result.tree.nodes.size() << " nodes");
    } catch (const std::exception& e) {
      return planError(e, &response);
    }
    return true;
  }

  static bool planError(const std::exception& e, PlanPath::Response* response) {
    response->success = false;
    response->message = std::string("planner error: ") + e.what();
    ROS_ERROR_STREAM("plan_path: " << response->message);
    return true;  // the client gets success: false and the message
  }

  /// When an ordinary request stops waiting for a thread: after its own time budget.
  static PlanSlots::Clock::time_point deadlineOf(const planning::PlannerOptions& options) {
    return PlanSlots::Clock::now() + std::chrono::duration_cast<PlanSlots::Clock::duration>(
                                         std::chrono::duration<double>(options.max_planning_time));
  }

  // A map arrives (latched: at once after subscribing, then on every change): inflated here,
  // then used by the requests that arrive after it. A message that is not a map is ignored.
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& message) {
    auto grid = std::make_shared<geometry::OccupancyGrid>();
    const std::string error = nodes::fromMapMessage(*message, grid.get());
    if (!error.empty()) {
      ROS_WARN_STREAM("rrt_planner: ignoring the map on " << map_sub_.getTopic() << ": " << error
                                                          << " (plans keep the previous map)");
      return;
    }
    if (!message->header.frame_id.empty() && message->header.frame_id != frame_id_) {
      ROS_WARN_STREAM("rrt_planner: the map on "
                      << map_sub_.getTopic() << " is in frame '" << message->header.frame_id
                      << "'; plans are given in ~frame_id '" << frame_id_ << "'");
    }
    const auto started = std::chrono::steady_clock::now();
    auto problem = std::make_shared<const planning::Problem>(
        planning::mapProblem(std::move(grid), defaults()->allow_unknown));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    {
      std::lock_guard<std::mutex> lock(map_mutex_);
      std::atomic_store(&map_, std::shared_ptr<const planning::Problem>(problem));
    }
    map_arrived_.notify_all();
    const geometry::OccupancyGrid& g = problem->map->grid();
    ROS_INFO("rrt_planner: map %d x %d cells of %g m from %s, inflated in %.0f ms", g.width,
             g.height, g.resolution, map_sub_.getTopic().c_str(), seconds * 1e3);
    // make_plan's regions (region_astar's, for ~robot_radius + ~clearance), built here rather
    // than by its first request (which waits for them if it comes first).
    const planning::PlannerOptions options = makePlanOptions(*defaults(), *problem);
    if (options.algorithm == planning::Algorithm::kRegionAStar) {
      const NodeDefaults& d = *defaults();
      const std::shared_ptr<const planning::GridRegions> regions =
          problem->regions->get(mapRobotRadius(d) + d.clearance);
      ROS_INFO("rrt_planner: make_plan's regions of the map built in %.0f ms (%d regions)",
               regions->buildSeconds() * 1e3, regions->regionCount());
    }
  }

  /// The map plans use: the latest from ~map_topic, else ~world_file's, else nullptr.
  std::shared_ptr<const planning::Problem> currentMap() const {
    std::shared_ptr<const planning::Problem> map = std::atomic_load(&map_);
    return map ? map : defaults()->world_map;
  }

  /// currentMap(), waiting up to kFirstMapWait for the first map on ~map_topic when there is
  /// none yet (right after start-up the latched map is still on its way, as move_base waits for
  /// its costmap's). nullptr and a warning for `service` saying so when none comes.
  std::shared_ptr<const planning::Problem> waitForMap(const char* service) {
    std::shared_ptr<const planning::Problem> map = currentMap();
    if (map) return map;
    if (map_sub_) {
      const auto deadline = std::chrono::steady_clock::now() + kFirstMapWait;
      std::unique_lock<std::mutex> lock(map_mutex_);
      // In slices, so that a shutdown (Ctrl-C) is not held up.
      while (!(map = currentMap()) && ros::ok() && std::chrono::steady_clock::now() < deadline) {
        map_arrived_.wait_for(lock, std::chrono::milliseconds(100));
      }
    }
    if (!map) {
      ROS_WARN_STREAM(service << ": no map yet: "
                              << (map_sub_ ? "none came on " + map_sub_.getTopic() + " within " +
                                                 std::to_string(kFirstMapWait.count()) +
                                                 " s (is a map_server or roomba_sim publishing it?)"
                                           : std::string("~map_topic is \"\""))
                              << ", and ~world_file is not a map");
    }
    return map;
  }

  // A pose of a request in ~frame_id (the map's): as given when its frame is ~frame_id or empty,
  // otherwise transformed with tf2 (the newest transform, waiting up to kTransformWait).
  std::optional<robot::Pose2D> inMapFrame(const geometry_msgs::PoseStamped& pose,
                                          const std::string& field, std::string* why) const {
    const auto& p = pose.pose.position;
    const auto& q = pose.pose.orientation;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(q.x) || !std::isfinite(q.y) ||
        !std::isfinite(q.z) || !std::isfinite(q.w)) {
      *why = field + ".pose: must be finite";
      return std::nullopt;
    }
    // "/map" is "map" (ROS 1's tools read it so; tf2 would warn at every try while waiting).
    const std::string frame = nodes::tfFrameId(pose.header.frame_id);
    const std::string map_frame = nodes::tfFrameId(frame_id_);
    if (frame.empty() || frame == map_frame) {
      return robot::Pose2D{p.x, p.y, nodes::quaternionToYaw(q)};
    }
    geometry_msgs::TransformStamped t;
    try {
      constexpr double kTransformWait = 0.5;  // s
      t = tf_buffer_.lookupTransform(map_frame, frame, ros::Time(0), ros::Duration(kTransformWait));
    } catch (const tf2::TransformException& e) {
      *why = field + ".header.frame_id: no transform from '" + frame + "' to '" + frame_id_ +
             "': " + e.what();
      return std::nullopt;
    }
    const double yaw = nodes::quaternionToYaw(t.transform.rotation);
    const double c = std::cos(yaw), s = std::sin(yaw);
    return robot::Pose2D{t.transform.translation.x + c * p.x - s * p.y,
                         t.transform.translation.y + s * p.x + c * p.y,
                         yaw + nodes::quaternionToYaw(q)};
  }

  // ~make_plan (nav_msgs/GetPlan), move_base's convention: an empty plan when there is none,
  // with the reason in the log.
  bool makePlan(nav_msgs::GetPlan::Request& request, nav_msgs::GetPlan::Response& response) {
    response.plan.header.frame_id = frame_id_;
    response.plan.header.stamp = ros::Time::now();
    const std::shared_ptr<const planning::Problem> map = waitForMap("make_plan");
    if (!map) return true;
    std::string why;
    const std::optional<robot::Pose2D> start = inMapFrame(request.start, "start", &why);
    const std::optional<robot::Pose2D> goal =
        start ? inMapFrame(request.goal, "goal", &why) : std::nullopt;
    if (!start || !goal) {
      ROS_WARN_STREAM("make_plan: no plan: " << why);
      return true;
    }
    const NodeDefaults& d = *defaults();
    const MakePlanQuery query = resolveMakePlan(*map, *start, *goal, request.tolerance, d);
    if (!query.error.empty()) {
      ROS_WARN_STREAM("make_plan: no plan: " << query.error);
      return true;
    }
    const ResolvedRequest resolved{query.problem, query.options, ""};
    planning::PlanResult result;
    {
      // An interactive request, served first like an ordinary plan_path request; its thread is
      // held for the plan alone.
      const PlanSlots::Lease slot = slots_.acquireOrdinary(deadlineOf(d.options));
      if (!slot) {
        ROS_WARN("make_plan: busy: every planning thread (~threads) is taken; call again");
        return true;
      }
      result = plan(resolved, slot);
    }
    const ros::Time stamp = ros::Time::now();
    if (result.success) {
      // One pose per map cell (~plan_resolution), as navfn answers: local planners follow the
      // part of the plan inside their window.
      const double spacing = plan_resolution_ > 0 ? plan_resolution_ : map->map->grid().resolution;
      response.plan =
          toPlanMessage(planning::densify(result.path, spacing), query.goal_yaw, frame_id_, stamp);
    } else {
      ROS_WARN_STREAM("make_plan: no plan from (" << start->x << ", " << start->y << ") to ("
                                                  << goal->x << ", " << goal->y
                                                  << "): " << result.message);
    }
    tree_pub_.publish(markers(resolved.problem, result.tree, &result.path, stamp));
    path_pub_.publish(response.plan);
    return true;
  }

  planning::PlanResult plan(const ResolvedRequest& resolved, const PlanSlots::Lease& slot) const {
    // A node shutting down (Ctrl-C), or a newer request preempting this plan, stops it within
    // about a millisecond.
    const auto shutting_down = [&slot] {
      return slot.stopRequested() || ros::isShuttingDown() || !ros::ok();
    };
    if (!animate_) return planning::plan(resolved.problem, resolved.options, {}, 0, shutting_down);
    // Animation: publish the growing tree every ~animate_every iterations, at most
    // ~animate_rate times a second (the plan waits for the next frame so rviz can follow).
    ros::WallTime next_frame = ros::WallTime::now();
    const auto on_progress = [&](const planning::Tree& tree, int /*iteration*/) {
      const ros::WallDuration wait = next_frame - ros::WallTime::now();
      if (wait > ros::WallDuration(0)) wait.sleep();
      tree_pub_.publish(markers(resolved.problem, tree, nullptr, ros::Time::now()));
      next_frame = ros::WallTime::now() + animate_period_;
    };
    return planning::plan(resolved.problem, resolved.options, on_progress, animate_every_,
                          shutting_down);
  }

  visualization_msgs::MarkerArray markers(const planning::Problem& problem,
                                          const planning::Tree& tree,
                                          const std::vector<planning::Point2>* path,
                                          const ros::Time& stamp) const {
    MarkerScene scene;
    scene.problem = &problem;
    scene.tree = &tree;
    scene.path = path;
    scene.max_tree_nodes = static_cast<std::size_t>(max_marker_nodes_);
    return toMarkers(scene, frame_id_, stamp);
  }

  /// The defaults in force: a request takes a snapshot, dynamic_reconfigure swaps in new ones.
  std::shared_ptr<const NodeDefaults> defaults() const { return std::atomic_load(&defaults_); }

  /// dynamic_reconfigure (cfg/RrtPlanner.cfg): new defaults for the requests that arrive after
  /// the change (a plan running keeps its own); refused (and kept) when they are not valid.
  void startReconfigure(const ros::NodeHandle& pnh) {
    const NodeDefaults& d = *defaults();
    RrtPlannerConfig in_force;
    in_force.step = d.options.step;
    in_force.goal_bias = d.options.goal_bias;
    in_force.max_iterations = d.options.max_iterations;
    in_force.goal_tolerance = d.options.goal_tolerance;
    in_force.algorithm = planning::toString(d.options.algorithm);
    in_force.collision_check = planning::toString(d.options.collision);
    in_force.robot_radius = d.robot_radius;
    in_force.clearance = d.clearance;
    in_force.max_planning_time = d.options.max_planning_time;
    in_force.smooth = d.options.smooth;
    reconfigure_ = std::make_unique<nodes::Reconfigure<RrtPlannerConfig>>(
        pnh, in_force, [this](const RrtPlannerConfig& c) {
          auto next = std::make_shared<NodeDefaults>(*defaults());
          planning::PlannerOptions& o = next->options;
          o.step = c.step;
          o.goal_bias = c.goal_bias;
          o.max_iterations = c.max_iterations;
          o.goal_tolerance = c.goal_tolerance;
          const auto algorithm = planning::parseAlgorithm(c.algorithm);
          const auto collision = planning::parseCollisionCheck(c.collision_check);
          if (!algorithm) throw util::InvalidInput("algorithm", "unknown '" + c.algorithm + "'");
          if (!collision) {
            throw util::InvalidInput("collision_check", "unknown '" + c.collision_check + "'");
          }
          o.algorithm = *algorithm;
          o.collision = *collision;
          o.max_planning_time = c.max_planning_time;
          o.smooth = c.smooth;
          next->robot_radius = c.robot_radius;
          next->clearance = c.clearance;
          validateDefaults(*next);
          std::atomic_store(&defaults_, std::shared_ptr<const NodeDefaults>(std::move(next)));
        });
  }

  std::shared_ptr<const NodeDefaults> defaults_;
  std::unique_ptr<nodes::Reconfigure<RrtPlannerConfig>> reconfigure_;
  std::map<std::string, planning::Problem> scenarios_;
  std::string frame_id_;
  int max_marker_nodes_ = 0;
  double plan_resolution_ = 0;  // m between make_plan's poses; 0: the map's resolution
  bool animate_ = false;
  int animate_every_ = 1;
  ros::WallDuration animate_period_;
  ros::Publisher tree_pub_;
  ros::Publisher path_pub_;
  ros::ServiceServer service_;
  ros::ServiceServer make_plan_service_;
  std::shared_ptr<const planning::Problem> map_;  // the latest map received (atomic access)
  std::mutex map_mutex_;                          // with map_arrived_: waitForMap()
  std::condition_variable map_arrived_;
  ros::CallbackQueue map_queue_;
  ros::Subscriber map_sub_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_{tf_buffer_};
  PlanSlots slots_;
  // Last: stopped (its thread joined) before anything onMap() uses is destroyed.
  ros::AsyncSpinner map_spinner_{1, &map_queue_};
};

RrtPlanner::RrtPlanner(ros::NodeHandle& pnh, nodes::NodeParams& params)
    : node_(std::make_unique<RrtPlannerNode>(pnh, params)) {}
RrtPlanner::~RrtPlanner() = default;
int RrtPlanner::planThreads() const { return node_->planThreads(); }
int RrtPlanner::callbackThreads() const { return node_->callbackThreads(); }

}  // namespace roomba_rrt::planner_node
