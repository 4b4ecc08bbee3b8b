// roomba_coverage's runs: the simulation core and a behaviour in one process, in the lab's step
// order (contact → bumper → behaviour → move), deterministic by seed; one robot (with its path
// and CSV) or several (their union's coverage over time). The behaviour is the lab's FSM or BT,
// or the cleaning tree (config/roomba_coverage_tree.xml in navigation::NavBt, which also sees
// the robot's pose). With --lag the one robot's behaviour sees bumper and pose that many steps
// late, as over ROS.
#pragma once

#include <fstream>
#include <memory>
#include <vector>

#include "coverage_arguments.h"
#include "roomba_rrt/behavior/roomba_behavior.h"
#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/coverage/coverage_planner.h"
#include "roomba_rrt/navigation/nav_leaves.h"
#include "roomba_rrt/sim/multi_robot_simulator.h"
#include "roomba_rrt/sim/simulator.h"

namespace roomba_rrt::tools {

/// Simulated seconds at which the coverage is reported (those ≤ the duration).
inline constexpr double kCheckpoints[] = {60.0, 300.0, 600.0};
/// Simulated seconds between two points of a --plot curve.
inline constexpr double kCurveInterval = 5.0;

/// True when the run's last step is one of kCheckpoints' (the final coverage is already a row).
bool finalIsCheckpoint(double duration, double step);

/// Fractions of the reachable floor whose time a run reports (time to 90 / 95 / 99 %), and the
/// multiples of the ideal time at which it reports the coverage.
inline constexpr double kTargets[] = {0.90, 0.95, 0.99};
inline constexpr double kIdealMultiples[] = {1.5, 2.0, 2.5, 3.0};

/// The FSM or the BT (the lab's tree, or --tree's) with the rotation angle's seed.
std::unique_ptr<behavior::RoombaBehavior> makeBehavior(const CoverageArguments& o,
                                                       const behavior::RoombaParams& params,
                                                       unsigned seed);

/// What the cleaning tree (--behavior coverage) and the reachable floor need, made once per world:
/// the coverage planner (at the coverage grid's resolution, so that its lattice is the grid's
/// cells), the navigation leaves' configuration with the coverage leaves, and the reachable floor.
struct Cleaning {
  Cleaning(const world::World& world, const behavior::RoombaParams& params);

  std::shared_ptr<const coverage::CoveragePlanner> planner;
  navigation::NavLeafConfig config;  ///< for navigation::NavBt with the coverage leaves
  /// The floor the robot's disc can reach from the world's start pose (m²): the coverage
  /// planner's measure (its lattice points within the robot's radius of a centre the disc can
  /// reach), and all the floor (not inside a wall, obstacle or blocked map cell).
  double reachable_area = 0;
  double floor_area = 0;
  /// The reachable floor swept once by the robot's diameter at the lab's forward_speed (s).
  double ideal_time = 0;
};

/// One point of the path, for the picture.
struct PathPoint {
  double x, y;
  behavior::RoombaState state;
};

/// The outcome of one run.
struct Run {
  std::vector<double> coverage_at;  ///< at each checkpoint ≤ duration
  double final_coverage = 0;
  std::vector<PathPoint> path;  ///< only when drawing

  // Measured against the reachable floor (only with a Cleaning): the floor cells swept (the
  // simulator's coverage grid) over the planner's reachable area, at most 1.
  std::vector<double> reachable_at;  ///< at each checkpoint ≤ duration
  std::vector<double> at_ideal;      ///< at each of kIdealMultiples × ideal time (≤ duration)
  std::vector<double> time_to;       ///< s to each of kTargets; NaN when not reached
  std::vector<double> curve;         ///< at 0, kCurveInterval, 2 kCurveInterval, … ≤ duration
  double reachable_final = 0;
  int bumps = 0;  ///< times the bumper was pressed (a press lasting several steps counts once)
  /// --unknown: simulated s when exploring ended and cleaning began (NaN: never, or not asked).
  double explored_at = 0;
  /// --known-map: plans made (1 + the times the rest was seen blocked); 0 otherwise.
  int plans = 0;
  /// --unknown without a lidar (exploration::BumpClean): simulated s when no move was left and
  /// the robot stood for good (NaN: not within the run).
  bool by_touch = false;
  double done_at = 0;
};

/// One run of one robot from the simulator's reset state; writes the CSV when `csv` is given and
/// keeps the path when `keep_path`. `cleaning` is needed for --behavior coverage and gives the
/// reachable floor's measures (null: only the lab's measures, for fsm and bt).
Run simulate(const CoverageArguments& o, const behavior::RoombaParams& params, unsigned seed,
             std::ofstream* csv, bool keep_path, sim::Simulator& simulator,
             const Cleaning* cleaning = nullptr);

/// One run of several robots: their union's coverage at the checkpoints and over time.
struct FleetRun {
  std::vector<double> coverage_at;  ///< at each checkpoint ≤ duration
  double final_coverage = 0;
  std::vector<double> curve;  ///< at 0, kCurveInterval, 2 kCurveInterval, … ≤ duration
};

/// The lab's step order for every robot at once: all bumpers, every behaviour, every move. Robot
/// k of seed s runs with seed s + 1000 k.
FleetRun simulateFleet(const CoverageArguments& o, const behavior::RoombaParams& params,
                       unsigned seed, sim::MultiRobotSimulator& simulator);

}  // namespace roomba_rrt::tools
