// roomba_nav_eval's core: the simulator, a navigation tree and the in-process planner in one
// loop, deterministic by seed; random reachable goals one after another; what a user notices
// (reached, bumps, time, detour, planning time). ROS-free.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "roomba_rrt/exploration/known_map.h"
#include "roomba_rrt/navigation/nav_bt.h"
#include "roomba_rrt/sensors/scanner.h"
#include "roomba_rrt/sim/simulator.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::tools {

/// Length of a shortest path from `start` to `goal` for the world's robot disc (every point of
/// it at least robot_radius from walls and furniture), computed independently of the planner:
/// Dijkstra on a `cell`-sized grid with 16 neighbours over cells whose centre is free, then the
/// grid path pulled taut with exact segment tests (a segment is kept when its distance to every
/// circle and rectangle is at least the radius). The result is a feasible path, so it is never
/// shorter than the true shortest; it exceeds it by less than about 1 % plus a cell near tight
/// passages (16 neighbours alone: ≤ 2.7 %, the taut pull removes most of it). +inf when the
/// grid finds no way (start or goal not free, or a passage narrower than a cell).
double shortestDiscPathLength(const world::World& world, const robot::Pose2D& start,
                              const robot::Pose2D& goal, double cell = 0.02);

struct NavEvalOptions {
  int goals = 20;
  std::uint32_t seed = 1;
  double timeout_s = 120;          ///< robot seconds per goal before it counts as not reached
  double min_goal_distance = 0.5;  ///< m from the robot, so each goal is a real trip
  double clearance = navigation::kDefaultClearance;  ///< on top of the robot radius, m
  bool threaded_planner = false;  ///< plan on a worker thread (not deterministic)
  /// Each goal in a home the robot has never seen: it starts a fresh map where it stands and
  /// drives with its lidar (exploration::NavigateUnknown); the world's walls and furniture are
  /// the simulator's only.
  bool unknown = false;
  /// With `unknown`: the map the robot is given for each goal (a map_server YAML or a world file,
  /// perhaps stale: exploration::KnownMap); "" none.
  std::string known_map;
};

/// One goal's run.
struct GoalRun {
  robot::Pose2D start, goal;
  bool reached = false;
  int bumps = 0;                     ///< ticks with the bumper pressed
  double time_s = 0;                 ///< robot seconds from the goal to its end
  double driven_m = 0;               ///< length driven
  double shortest_m = 0;             ///< shortestDiscPathLength
  std::string message;               ///< why it was aborted
  int plans = 0;                     ///< --unknown: trees that planned it (1 + paths blocked)
  std::vector<robot::Pose2D> trace;  ///< poses, every 6th tick
};

struct NavEvalReport {
  std::vector<GoalRun> runs;
  std::vector<double> planning_ms;  ///< every plan's time (in-process)
  double reached_pct = 0;
  int bumps = 0;
  double mean_time_s = 0;        ///< over reached goals
  double mean_length_ratio = 0;  ///< driven ÷ shortest, over reached goals
  double planning_ms_p50 = 0;
};

/// One goal in a world the robot has never seen, from where `simulator`'s robot stands: a fresh
/// map there (exploration::NavigateUnknown with the tree in `tree_file`), `scanner`'s scans of the
/// lidar into it, until the goal ends or `timeout_s` robot seconds pass. `clock` (robot s, the
/// scanner's time) goes on across goals. The run's shortest_m is left 0. With `known`, the map
/// starts from that map of the home (perhaps stale: its walls, not its furniture).
GoalRun driveUnknown(sim::Simulator& simulator, sensors::Scanner& scanner,
                     const std::string& tree_file, const robot::Pose2D& goal, std::uint32_t seed,
                     double timeout_s, double& clock, const exploration::KnownMap* known = nullptr);

/// Runs `options.goals` random reachable goals (a free pose for the robot's disc with a finite
/// shortest path, at least min_goal_distance away) one after another from the world's initial
/// pose. `progress(done, total)` is called after each goal.
NavEvalReport evaluateNavigation(const world::World& world, const std::string& tree_file,
                                 const NavEvalOptions& options,
                                 const std::function<void(int, int)>& progress = {});

/// {"goals": N, "reached_pct": …, "bumps": …, "mean_time_s": …, "mean_length_ratio": …,
///  "planning_ms_p50": …}
std::string toJson(const NavEvalReport& report);

}  // namespace roomba_rrt::tools
