#include "coverage_run.h"

#include <cmath>
#include <iterator>

#include "roomba_rrt/behavior/roomba_bt.h"
#include "roomba_rrt/behavior/roomba_fsm.h"

namespace roomba_rrt::tools {

bool finalIsCheckpoint(double duration, double step) {
  for (double t : kCheckpoints) {
    if (std::lround(t / step) == std::lround(duration / step)) return true;
  }
  return false;
}

std::unique_ptr<behavior::RoombaBehavior> makeBehavior(const CoverageOptions& o,
                                                       const behavior::RoombaParams& params,
                                                       unsigned seed) {
  if (o.behavior == "fsm") return std::make_unique<behavior::RoombaFsm>(params, seed);
  if (o.tree.empty()) return std::make_unique<behavior::RoombaBt>(params, seed);
  return std::make_unique<behavior::RoombaBt>(params, seed, o.tree);
}

Run simulate(const CoverageOptions& o, const behavior::RoombaParams& params, unsigned seed,
             std::ofstream* csv, bool keep_path, sim::Simulator& simulator) {
  simulator.reset();
  const double step = simulator.world().step;
  std::unique_ptr<behavior::RoombaBehavior> behavior = makeBehavior(o, params, seed);
  const long steps = std::lround(o.duration / step);
  Run run;
  std::size_t next_checkpoint = 0;
  double theta = simulator.pose().theta, previous_wrapped = theta;
  for (long k = 0; k < steps; ++k) {
    const robot::BumperState bumper = simulator.senseContact();
    const robot::Pose2D pose = simulator.pose();  // the pose the behaviour sees
    const robot::Velocity cmd = behavior->tick(bumper);
    if (csv || keep_path) {
      theta += std::remainder(pose.theta - previous_wrapped, 2 * M_PI);  // unwrapped θ
      previous_wrapped = pose.theta;
    }
    if (csv) {
      *csv << k * step << ',' << pose.x << ',' << pose.y << ',' << theta << ',' << cmd.v << ','
           << cmd.w << ',' << behavior->stateName() << ',' << (bumper.pressed ? 1 : 0) << '\n';
    }
    if (keep_path) run.path.push_back({pose.x, pose.y, behavior->state()});
    simulator.move(cmd);
    while (next_checkpoint < std::size(kCheckpoints) &&
           std::lround(kCheckpoints[next_checkpoint] / step) == k + 1) {
      run.coverage_at.push_back(simulator.coverage());
      ++next_checkpoint;
    }
  }
  run.final_coverage = simulator.coverage();
  return run;
}

FleetRun simulateFleet(const CoverageOptions& o, const behavior::RoombaParams& params,
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
