// Speed of the range sensors' core (Google Benchmark): rays cast per second by a 360-ray LDS
// scan in the furnished room and on willow_full (target ≥ 10 M rays/s), the caster's one-time
// build on willow_full, and the cost of ten robots' lidars (5 Hz) per simulator step. Numbers:
// doc/simulation.md, "Sensors".
//   devel/lib/roomba_rrt/sensor_bench
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>
#include <random>
#include <vector>

#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/sensors/scanner.h"
#include "roomba_rrt/sim/multi_robot_simulator.h"
#include "roomba_rrt/world/world_file.h"

namespace {

using namespace roomba_rrt;

world::World furnishedRoom() {
  return world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml");
}

/// 1024 poses where the robot's disc is free, at random headings.
std::vector<robot::Pose2D> freePoses(const world::World& world) {
  std::mt19937 rng(5);
  const world::Room& room = world.room;
  std::uniform_real_distribution<double> x(room.origin.x, room.origin.x + room.width);
  std::uniform_real_distribution<double> y(room.origin.y, room.origin.y + room.height);
  std::uniform_real_distribution<double> theta(-3.14159, 3.14159);
  std::vector<robot::Pose2D> poses;
  while (poses.size() < 1024) {
    const robot::Pose2D p{x(rng), y(rng), theta(rng)};
    if (!world::penetrates(world, p.x, p.y)) poses.push_back(p);
  }
  return poses;
}

/// One LDS scan (360 rays) per iteration from the poses in turn; items/s = rays/s.
void scanRays(benchmark::State& state, const world::World& world, double range_max) {
  const sensors::RayCaster caster(world.room);
  sensors::RangeSensorSpec lds = sensors::ldsPreset();
  lds.range_max = range_max;
  const sensors::RayFan fan(lds);
  const std::vector<robot::Pose2D> poses = freePoses(world);
  std::mt19937 noise;
  std::vector<float> ranges;
  std::size_t i = 0;
  for (auto _ : state) {
    sensors::measure(caster, lds, fan, poses[i++ & 1023], {}, noise, ranges);
    benchmark::DoNotOptimize(ranges.data());
  }
  state.SetItemsProcessed(state.iterations() * lds.samples);
}

void BM_LdsScanFurnishedRoom(benchmark::State& state) { scanRays(state, furnishedRoom(), 3.5); }
BENCHMARK(BM_LdsScanFurnishedRoom);

std::shared_ptr<const world::World> willowFull() {
  static std::shared_ptr<const world::World> world = [] {
    const std::string path = ROOMBA_RRT_SHARED_MAPS "/willow_full.yaml";
    if (!std::filesystem::exists(path)) return std::shared_ptr<const world::World>();
    return std::make_shared<const world::World>(world::readWorldFile(path).world);
  }();
  return world;
}

/// willow_full (540 x 587 cells of 0.1 m) at the LDS's 3.5 m and at 30 m (a long-range lidar: many
/// more cells per ray).
void BM_LdsScanWillowFull(benchmark::State& state) {
  const auto world = willowFull();
  if (!world) {
    state.SkipWithError("needs ../shared/maps/willow_full.yaml");
    return;
  }
  scanRays(state, *world, static_cast<double>(state.range(0)) / 10);
}
BENCHMARK(BM_LdsScanWillowFull)->Arg(35)->Arg(300);

/// What a simulator with sensors pays once when it loads willow_full: the caster's bits of the
/// map's blocked cells, along its rows and its columns.
void BM_BuildCasterWillowFull(benchmark::State& state) {
  const auto world = willowFull();
  if (!world) {
    state.SkipWithError("needs ../shared/maps/willow_full.yaml");
    return;
  }
  for (auto _ : state) {
    const sensors::RayCaster caster(world->room);
    benchmark::DoNotOptimize(&caster);
  }
  state.SetItemsProcessed(state.iterations() * world->room.map->cells.size());
}
BENCHMARK(BM_BuildCasterWillowFull)->Unit(benchmark::kMillisecond);

/// Ten robots in the furnished room (spreadRobots) turning in place, each with the LDS at 5 Hz
/// (arg 1) or none (arg 0): the simulator's step plus the scans due at it, per step.
void BM_StepTenRobotsWithLidar(benchmark::State& state) {
  world::World world = furnishedRoom();
  world.robots = sim::spreadRobots(world, 10);
  for (auto& robot : world.robots) {
    robot.sensors.clear();
    if (state.range(0)) robot.sensors.push_back(sensors::ldsPreset());
  }
  sim::MultiRobotSimulator sim(world);
  sensors::Scanner scanner(world);
  std::vector<robot::Velocity> commands(10, robot::Velocity{0.3, 0.8});
  std::vector<robot::Pose2D> poses(10);
  for (auto _ : state) {
    sim.step(commands);
    for (std::size_t r = 0; r < 10; ++r) poses[r] = sim.pose(r);
    benchmark::DoNotOptimize(scanner.scan(sim.time(), poses).data());
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["sim_s_per_wall_s"] =
      benchmark::Counter(state.iterations() * world.step, benchmark::Counter::kIsRate);
  state.counters["rays"] = static_cast<double>(scanner.rays());
}
BENCHMARK(BM_StepTenRobotsWithLidar)->Arg(0)->Arg(1);

}  // namespace

BENCHMARK_MAIN();
