// Speed of the simulation core (Google Benchmark). Numbers: doc/performance.md.
//   devel/lib/roomba_rrt/sim_bench   (after scripts/bench or any Release build)
// The commands imitate the lab behaviour's mix (forward, spiral-like arcs, backing up, turning
// in place), held for a random number of steps, so the robot keeps hitting walls and furniture.
#include <benchmark/benchmark.h>

#include <time.h>

#include <random>
#include <vector>

#include "roomba_rrt/robot/unicycle.h"
#include "roomba_rrt/sim/contact.h"
#include "roomba_rrt/sim/multi_robot_simulator.h"
#include "roomba_rrt/sim/simulator.h"
#include "roomba_rrt/world/world_file.h"

namespace {

using namespace roomba_rrt::robot;
using namespace roomba_rrt::sim;
using namespace roomba_rrt::world;

World furnishedRoom() { return loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml"); }

/// 2^16 commands, one per step, in runs of 1–180 steps.
std::vector<Velocity> commandTape() {
  std::mt19937 rng(7);
  const std::vector<Velocity> kinds = {{0.5, 0.0}, {0.5, 1.2}, {0.5, 0.6}, {-0.1, 0.0}, {0.0, 0.5}};
  std::uniform_int_distribution<std::size_t> kind(0, kinds.size() - 1);
  std::uniform_int_distribution<int> hold(1, 180);
  std::vector<Velocity> tape;
  while (tape.size() < (1u << 16)) {
    const Velocity cmd = kinds[kind(rng)];
    for (int i = hold(rng); i > 0 && tape.size() < (1u << 16); --i) tape.push_back(cmd);
  }
  return tape;
}

/// One lab step (senseContact + move), the unit the ≥ 5 M steps/s target is about.
void runSteps(benchmark::State& state, const World& world) {
  Simulator sim(world);
  const std::vector<Velocity> tape = commandTape();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sim.step(tape[i++ & (tape.size() - 1)]));
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["coverage"] = sim.coverage();
}

void BM_StepLabRoomFiveFurniture(benchmark::State& state) { runSteps(state, furnishedRoom()); }
BENCHMARK(BM_StepLabRoomFiveFurniture);

void BM_StepLabRoomEmpty(benchmark::State& state) { runSteps(state, World{}); }
BENCHMARK(BM_StepLabRoomEmpty);

/// An hour of robot time at 60 Hz (216,000 steps) in the furnished room; target < 50 ms.
void BM_HourOfRobotTime(benchmark::State& state) {
  const World world = furnishedRoom();
  const std::vector<Velocity> tape = commandTape();
  for (auto _ : state) {
    Simulator sim(world);
    for (std::size_t i = 0; i < 216000; ++i) sim.step(tape[i & (tape.size() - 1)]);
    benchmark::DoNotOptimize(sim.pose());
  }
}
BENCHMARK(BM_HourOfRobotTime)->Unit(benchmark::kMillisecond);

/// Issue 13: n robots in the furnished room (spreadRobots), each on the command tape at its own
/// offset, so they keep meeting walls, furniture and each other. items/s counts robot-steps;
/// `per_robot_vs_one` is the time per robot-step over the time of one Simulator step measured
/// the same way in the same world (target: ≤ 2 at 100 robots).
/// CPU seconds of this thread (other processes on the machine do not count).
double threadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

double secondsPerSimulatorStep(const World& world, const std::vector<Velocity>& tape) {
  Simulator sim(world);
  const double begin = threadSeconds();
  const std::size_t steps = 1u << 20;
  for (std::size_t i = 0; i < steps; ++i) sim.step(tape[i & (tape.size() - 1)]);
  benchmark::DoNotOptimize(sim.pose());
  return (threadSeconds() - begin) / steps;
}

void BM_StepRobotsFurnishedRoom(benchmark::State& state) {
  World world = furnishedRoom();
  const int n = static_cast<int>(state.range(0));
  world.robots = spreadRobots(world, n);
  MultiRobotSimulator sim(world);
  const std::vector<Velocity> tape = commandTape();
  std::vector<Velocity> commands(n);
  std::size_t i = 0;
  const double begin = threadSeconds();
  for (auto _ : state) {
    for (int r = 0; r < n; ++r) commands[r] = tape[(i + 4099 * r) & (tape.size() - 1)];
    sim.step(commands);
    ++i;
  }
  const double per_step = (threadSeconds() - begin) / i;
  state.SetItemsProcessed(state.iterations() * n);
  state.counters["steps/s"] = 1.0 / per_step;
  state.counters["per_robot_vs_one"] =
      per_step / n / secondsPerSimulatorStep(furnishedRoom(), tape);
  state.counters["union_coverage"] = sim.unionCoverage();
}
BENCHMARK(BM_StepRobotsFurnishedRoom)->Arg(1)->Arg(10)->Arg(100);

// The parts of a step, for finding where the time goes.
void BM_IntegrateArc(benchmark::State& state) {
  Pose2D pose{3.2, 2.4, 0.0};
  for (auto _ : state) {
    pose = integrateArc(pose, {0.5, 0.8}, 1.0 / 60.0);
    benchmark::DoNotOptimize(pose);
  }
}
BENCHMARK(BM_IntegrateArc);

void BM_SenseBumperFiveFurniture(benchmark::State& state) {
  const World world = furnishedRoom();
  const Pose2D pose{3.2, 2.4, 0.3};
  for (auto _ : state) benchmark::DoNotOptimize(senseBumper(world, pose));
}
BENCHMARK(BM_SenseBumperFiveFurniture);

void BM_MarkCoverageDisc(benchmark::State& state) {
  const World world = furnishedRoom();
  CoverageGrid grid(world);
  double x = 1.0;
  for (auto _ : state) {
    grid.markDisc(x, 2.4, world.robot().radius);
    x = x > 5.0 ? 1.0 : x + 0.008;
  }
}
BENCHMARK(BM_MarkCoverageDisc);

}  // namespace

BENCHMARK_MAIN();
