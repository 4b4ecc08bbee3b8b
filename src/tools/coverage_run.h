// roomba_coverage's runs: the simulation core and a behaviour in one process, in the lab's step
// order (contact → bumper → behaviour → move), deterministic by seed; one robot (with its path
// and CSV) or several (their union's coverage over time).
#pragma once

#include <fstream>
#include <memory>
#include <vector>

#include "coverage_arguments.h"
#include "roomba_rrt/behavior/roomba_behavior.h"
#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/sim/multi_robot_simulator.h"
#include "roomba_rrt/sim/simulator.h"

namespace roomba_rrt::tools {

/// Simulated seconds at which the coverage is reported (those ≤ the duration).
inline constexpr double kCheckpoints[] = {60.0, 300.0, 600.0};
/// Simulated seconds between two points of a --plot curve.
inline constexpr double kCurveInterval = 5.0;

/// True when the run's last step is one of kCheckpoints' (the final coverage is already a row).
bool finalIsCheckpoint(double duration, double step);

/// The FSM or the BT (the lab's tree, or --tree's) with the rotation angle's seed.
std::unique_ptr<behavior::RoombaBehavior> makeBehavior(const CoverageOptions& o,
                                                       const behavior::RoombaParams& params,
                                                       unsigned seed);

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
};

/// One run of one robot from the simulator's reset state; writes the CSV when `csv` is given and
/// keeps the path when `keep_path`.
Run simulate(const CoverageOptions& o, const behavior::RoombaParams& params, unsigned seed,
             std::ofstream* csv, bool keep_path, sim::Simulator& simulator);

/// One run of several robots: their union's coverage at the checkpoints and over time.
struct FleetRun {
  std::vector<double> coverage_at;  ///< at each checkpoint ≤ duration
  double final_coverage = 0;
  std::vector<double> curve;  ///< at 0, kCurveInterval, 2 kCurveInterval, … ≤ duration
};

/// The lab's step order for every robot at once: all bumpers, every behaviour, every move. Robot
/// k of seed s runs with seed s + 1000 k.
FleetRun simulateFleet(const CoverageOptions& o, const behavior::RoombaParams& params,
                       unsigned seed, sim::MultiRobotSimulator& simulator);

}  // namespace roomba_rrt::tools
