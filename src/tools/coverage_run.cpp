#include "coverage_run.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <iterator>
#include <stdexcept>
#include <utility>

#include "roomba_rrt/behavior/roomba_bt.h"
#include "roomba_rrt/behavior/roomba_fsm.h"
#include "roomba_rrt/coverage/coverage_leaves.h"
#include "roomba_rrt/exploration/bump_clean.h"
#include "roomba_rrt/exploration/clean_known_map.h"
#include "roomba_rrt/exploration/explore_clean.h"
#include "roomba_rrt/mapping/sensor_scan.h"
#include "roomba_rrt/navigation/nav_bt.h"
#include "roomba_rrt/sensors/scanner.h"

namespace roomba_rrt::tools {
namespace {

/// What drives the robot: the lab's FSM or BT (bumper in), the cleaning tree (bumper and pose
/// in), or the cleaning of an unknown world (bumper, pose and the lidar's scans in; without a
/// lidar, the IR light bumper's: exploration::BumpClean).
class Driver {
 public:
  Driver(const CoverageArguments& o, const behavior::RoombaParams& params, unsigned seed,
         const world::World& world, const Cleaning* cleaning) {
    if (o.behavior == "unknown" || o.behavior == "known-map") {
      // The world's walls, furniture and map are never looked at: the robot and its start only
      // (and the map it is given).
      robot_ = world.robot();
      if (o.behavior == "known-map") {
        if (robot_.sensors.empty()) {
          throw util::InvalidInput("sensors",
                                   "cleaning with a known map needs a range sensor on the "
                                   "robot (a world file without `sensors:` has the lidar)");
        }
        known_ = std::make_unique<exploration::CleanKnownMap>(
            robot_, exploration::loadKnownMap(o.known_map), world.coverage_cell_size, params, seed,
            o.predictTicks() / params.rate, ROOMBA_RRT_CONFIG_DIR "/roomba_coverage_tree.xml");
        return;
      }
      if (exploration::cleansByTouch(robot_)) {  // no lidar: bumper and IR light bumper
        touch_ = std::make_unique<exploration::BumpClean>(robot_, params);
        return;
      }
      explore_ = std::make_unique<exploration::ExploreClean>(
          robot_, world.coverage_cell_size, params, seed, o.predictTicks() / params.rate,
          exploration::ExploreCleanTrees{ROOMBA_RRT_CONFIG_DIR "/roomba_nav_tree.xml",
                                         ROOMBA_RRT_CONFIG_DIR "/roomba_coverage_tree.xml",
                                         ROOMBA_RRT_CONFIG_DIR "/roomba_touch_up_tree.xml"});
      return;
    }
    if (o.behavior != "coverage") {
      lab_ = makeBehavior(o, params, seed);
      return;
    }
    if (!cleaning) throw std::logic_error("--behavior coverage needs the cleaning set up");
    navigation::NavLeafConfig config = cleaning->config;
    config.pose_latency = o.predictTicks() / params.rate;  // as roomba_bt's ~pose_latency
    tree_ = std::make_unique<navigation::NavBt>(
        config, seed,
        o.tree.empty() ? std::string(ROOMBA_RRT_CONFIG_DIR "/roomba_coverage_tree.xml") : o.tree);
  }
  bool sees() const { return explore_ || known_ || touch_; }
  /// The trees are told the times as roomba_bt tells them: the tick's and the pose's.
  robot::Velocity tick(const robot::BumperState& bumper, const robot::Pose2D& pose, double now,
                       double pose_stamp, const std::vector<sensors::Scan>& scans,
                       const robot::Pose2D& scan_pose) {
    if (sees()) {
      for (const sensors::Scan& scan : scans) {
        if (scan.robot != 0) continue;
        const sensors::RangeSensorSpec& spec = robot_.sensors[scan.sensor];
        const robot::Pose2D sensor = mapping::mountedPose(scan_pose, spec.mount);
        const mapping::ScanView view = mapping::scanView(spec, scan.ranges);
        explore_ ? explore_->addScan(sensor, view)
        : known_ ? known_->addScan(sensor, view)
                 : touch_->addScan(sensor, view);
      }
      if (touch_) return touch_->tick(now, bumper, pose);
      return explore_ ? explore_->tick(now, bumper, pose, pose_stamp)
                      : known_->tick(now, bumper, pose, pose_stamp);
    }
    if (lab_) return lab_->tick(bumper);
    tree_->observeTiming(now, pose_stamp);
    return tree_->tick(bumper, pose);
  }
  const std::string& stateName() const {
    return known_     ? known_->stateName()
           : touch_   ? touch_->stateName()
           : explore_ ? explore_->stateName()
           : lab_     ? lab_->stateName()
                      : tree_->stateName();
  }
  behavior::RoombaState state() const {
    return known_     ? known_->state()
           : touch_   ? touch_->state()
           : explore_ ? explore_->state()
           : lab_     ? lab_->state()
                      : tree_->state();
  }
  double exploredAt() const { return explore_ ? explore_->exploredAt() : -1; }
  int plans() const { return known_ ? known_->plans() : 0; }
  /// By touch: simulated s when no move was left (negative: not yet, or not by touch).
  double doneAt() const { return touch_ ? touch_->doneAt() : -1; }
  bool byTouch() const { return touch_ != nullptr; }

 private:
  std::unique_ptr<exploration::CleanKnownMap> known_;
  std::unique_ptr<behavior::RoombaBehavior> lab_;
  std::unique_ptr<navigation::NavBt> tree_;
  std::unique_ptr<exploration::ExploreClean> explore_;
  std::unique_ptr<exploration::BumpClean> touch_;  ///< unknown, no lidar (cleansByTouch)
  world::RobotSpec robot_;  ///< whose sensors explore_'s or touch_'s scans come from
};

/// Fraction of the reachable floor the robot has swept.
double reachableCoverage(const sim::Simulator& simulator, const Cleaning& cleaning) {
  const sim::CoverageGrid& grid = simulator.coverageGrid();
  const double swept =
      static_cast<double>(grid.sweptFreeCells()) * grid.cellSize() * grid.cellSize();
  return cleaning.reachable_area > 0 ? std::min(1.0, swept / cleaning.reachable_area) : 0.0;
}

}  // namespace

Cleaning::Cleaning(const world::World& world, const behavior::RoombaParams& params) {
  planner =
      std::make_shared<const coverage::CoveragePlanner>(world, coverage::cleaningOptions(world));
  const coverage::CoveragePlan plan =
      planner->plan({world.robot().initial_pose.x, world.robot().initial_pose.y});
  reachable_area = plan.reachable_area;
  floor_area = plan.floor_area;
  ideal_time = reachable_area / (2 * world.robot().radius * params.forward_speed);
  config = exploration::cleaningConfig(world, params, planner);
}

bool finalIsCheckpoint(double duration, double step) {
  for (double t : kCheckpoints) {
    if (std::lround(t / step) == std::lround(duration / step)) return true;
  }
  return false;
}

std::unique_ptr<behavior::RoombaBehavior> makeBehavior(const CoverageArguments& o,
                                                       const behavior::RoombaParams& params,
                                                       unsigned seed) {
  if (o.behavior == "fsm") return std::make_unique<behavior::RoombaFsm>(params, seed);
  if (o.tree.empty()) return std::make_unique<behavior::RoombaBt>(params, seed);
  return std::make_unique<behavior::RoombaBt>(params, seed, o.tree);
}

Run simulate(const CoverageArguments& o, const behavior::RoombaParams& params, unsigned seed,
             std::ofstream* csv, bool keep_path, sim::Simulator& simulator,
             const Cleaning* cleaning) {
  simulator.reset();
  const double step = simulator.world().step;
  Driver behavior(o, params, seed, simulator.world(), cleaning);
  // The lidar's scans, for a driver that maps (none is taken for the others: same runs as
  // before sensors existed).
  std::unique_ptr<sensors::Scanner> scanner;
  if (behavior.sees()) scanner = std::make_unique<sensors::Scanner>(simulator.world());
  const std::vector<sensors::Scan> no_scans;
  std::vector<robot::Pose2D> scan_poses(1);  // the one robot's, for the scanner
  const long steps = std::lround(o.duration / step);
  Run run;
  std::size_t next_checkpoint = 0, next_ideal = 0;
  const long per_point = std::max(1L, std::lround(kCurveInterval / step));
  if (cleaning) {
    run.time_to.assign(std::size(kTargets), std::nan(""));
    run.curve.push_back(reachableCoverage(simulator, *cleaning));
  }
  bool was_pressed = simulator.senseContact().pressed;  // put down touching a wall: no bump
  double theta = simulator.pose().theta, previous_wrapped = theta;
  // What the behaviour sees, o.lag steps late (over ROS, pose and bumper are messages: one step).
  std::deque<std::pair<robot::BumperState, robot::Pose2D>> seen;
  for (long k = 0; k < steps; ++k) {
    const robot::BumperState bumper = simulator.senseContact();
    run.bumps += bumper.pressed && !was_pressed;
    was_pressed = bumper.pressed;
    const robot::Pose2D pose = simulator.pose();  // written and drawn: where the robot is
    seen.emplace_back(bumper, pose);
    if (seen.size() > static_cast<std::size_t>(o.lag) + 1) seen.pop_front();
    scan_poses[0] = pose;
    const std::vector<sensors::Scan>& scans =
        scanner ? scanner->scan(k * step, scan_poses) : no_scans;
    const robot::Velocity cmd =
        behavior.tick(seen.front().first, seen.front().second, k * step,
                      (k - static_cast<long>(seen.size()) + 1) * step, scans, pose);
    if (csv || keep_path) {
      theta += std::remainder(pose.theta - previous_wrapped, 2 * M_PI);  // unwrapped θ
      previous_wrapped = pose.theta;
    }
    if (csv) {
      *csv << k * step << ',' << pose.x << ',' << pose.y << ',' << theta << ',' << cmd.v << ','
           << cmd.w << ',' << behavior.stateName() << ',' << (bumper.pressed ? 1 : 0) << '\n';
    }
    if (keep_path) run.path.push_back({pose.x, pose.y, behavior.state()});
    simulator.move(cmd);
    while (next_checkpoint < std::size(kCheckpoints) &&
           std::lround(kCheckpoints[next_checkpoint] / step) == k + 1) {
      run.coverage_at.push_back(simulator.coverage());
      if (cleaning) run.reachable_at.push_back(reachableCoverage(simulator, *cleaning));
      ++next_checkpoint;
    }
    if (!cleaning) continue;
    const double reached = reachableCoverage(simulator, *cleaning);
    for (std::size_t t = 0; t < std::size(kTargets); ++t) {
      if (std::isnan(run.time_to[t]) && reached >= kTargets[t]) run.time_to[t] = (k + 1) * step;
    }
    while (next_ideal < std::size(kIdealMultiples) &&
           std::lround(kIdealMultiples[next_ideal] * cleaning->ideal_time / step) <= k + 1) {
      run.at_ideal.push_back(reached);
      ++next_ideal;
    }
    if ((k + 1) % per_point == 0) run.curve.push_back(reached);
  }
  run.final_coverage = simulator.coverage();
  if (cleaning) run.reachable_final = reachableCoverage(simulator, *cleaning);
  run.explored_at = behavior.exploredAt() >= 0 ? behavior.exploredAt() : std::nan("");
  run.plans = behavior.plans();
  run.by_touch = behavior.byTouch();
  run.done_at = behavior.doneAt() >= 0 ? behavior.doneAt() : std::nan("");
  return run;
}

FleetRun simulateFleet(const CoverageArguments& o, const behavior::RoombaParams& params,
                       unsigned seed, sim::MultiRobotSimulator& simulator) {
  simulator.reset();
  std::vector<std::unique_ptr<behavior::RoombaBehavior>> behaviors;
  for (std::size_t i = 0; i < simulator.size(); ++i) {
    behaviors.push_back(makeBehavior(o, params, seed + 1000u * static_cast<unsigned>(i)));
  }
  std::vector<robot::Velocity> commands(simulator.size());
  const double step = simulator.world().step;
  const long steps = std::lround(o.duration / step);
  const long per_point = std::max(1L, std::lround(kCurveInterval / step));
  FleetRun run;
  run.curve.push_back(simulator.unionCoverage());
  std::size_t next_checkpoint = 0;
  for (long k = 0; k < steps; ++k) {
    simulator.senseContact();
    for (std::size_t i = 0; i < commands.size(); ++i) {
      commands[i] = behaviors[i]->tick(simulator.bumper(i));
    }
    simulator.move(commands);
    while (next_checkpoint < std::size(kCheckpoints) &&
           std::lround(kCheckpoints[next_checkpoint] / step) == k + 1) {
      run.coverage_at.push_back(simulator.unionCoverage());
      ++next_checkpoint;
    }
    if ((k + 1) % per_point == 0) run.curve.push_back(simulator.unionCoverage());
  }
  run.final_coverage = simulator.unionCoverage();
  return run;
}

}  // namespace roomba_rrt::tools
