// Time to plan coverage (Google Benchmark); the target is ≤ 10 ms for the furnished room.
//   devel/lib/roomba_rrt/coverage_bench   (after scripts/bench or any Release build)
// BM_CoveragePlanFurnished is what a behaviour pays when it starts cleaning: sampling the world
// (CoveragePlanner's constructor) and planning from the robot's pose. The counters report what
// the plan achieves: the rows' share of the reachable floor and the plan's length against the
// ideal (the reachable floor swept once by the robot's diameter). BM_CoveragePlanWillowFull and
// BM_CoverageTouchUpWillowFull are a whole shared map (skipped when ../shared/maps is not there).
// BM_CoverageRepairFurnished is a replan of the stale map's cleaning (issue 43).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "roomba_rrt/coverage/coverage_planner.h"
#include "roomba_rrt/world/world.h"
#include "roomba_rrt/world/world_file.h"

namespace {

using namespace roomba_rrt;

void planAndReport(benchmark::State& state, const world::World& world) {
  const coverage::Point2 start{world.robot().initial_pose.x, world.robot().initial_pose.y};
  coverage::CoveragePlan plan;
  for (auto _ : state) {
    const coverage::CoveragePlanner planner(world);
    plan = planner.plan(start);
    benchmark::DoNotOptimize(plan.legs.data());
  }
  const double ideal = plan.reachable_area / (2 * world.robot().radius);
  state.counters["coverage_pct"] = 100 * plan.swept_area / plan.reachable_area;
  state.counters["plan_m"] = plan.length();
  state.counters["ideal_m"] = ideal;
  state.counters["row_m"] = plan.rowLength();
  state.counters["legs"] = static_cast<double>(plan.legs.size());
  state.counters["cells"] = plan.cells;
}

void BM_CoveragePlanFurnished(benchmark::State& state) {
  planAndReport(state, world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml"));
}
BENCHMARK(BM_CoveragePlanFurnished)->Unit(benchmark::kMillisecond);

// What a robot given the furnished room's map without its furniture (config/maps/
// furnished_walls.yaml) pays when its lidar shows the furniture across its rows
// (exploration/clean_known_map.h): a planner on the map as it is now (here the walls' map with
// the five pieces of furniture) and the rows left cut round them (CoveragePlanner::repair).
void BM_CoverageRepairFurnished(benchmark::State& state) {
  const world::World walls = world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/maps/furnished_walls.yaml",
                                              world::PoseSource::kElsewhere);
  const world::World furnished =
      world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml");
  world::World now = walls;
  now.room.circles = furnished.room.circles;
  now.room.rectangles = furnished.room.rectangles;
  const coverage::Point2 start{furnished.robot().initial_pose.x, furnished.robot().initial_pose.y};
  const coverage::CoveragePlan plan =
      coverage::CoveragePlanner(walls, coverage::cleaningOptions(furnished)).plan(start);
  coverage::CoveragePlan rest;
  for (auto _ : state) {
    const coverage::CoveragePlanner planner(now, coverage::cleaningOptions(furnished));
    rest = planner.repair(plan, 0, start);
    benchmark::DoNotOptimize(rest.legs.data());
  }
  state.counters["legs_before"] = static_cast<double>(plan.legs.size());
  state.counters["legs_after"] = static_cast<double>(rest.legs.size());
}
BENCHMARK(BM_CoverageRepairFurnished)->Unit(benchmark::kMillisecond);

void BM_CoveragePlanApartmentMap(benchmark::State& state) {
  planAndReport(state, world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/maps/apartment.yaml"));
}
BENCHMARK(BM_CoveragePlanApartmentMap)->Unit(benchmark::kMillisecond);

// A whole office floor (../shared/maps/willow_full: 2,900 m² of floor, 5 M lattice points), as
// `scripts/run clean --world willow_full.yaml` plans it: what a large map costs.
void BM_CoveragePlanWillowFull(benchmark::State& state) {
  const std::string yaml = ROOMBA_RRT_SHARED_MAPS "/willow_full.yaml";
  if (!std::filesystem::exists(yaml)) {
    state.SkipWithError(("no " + yaml).c_str());
    return;
  }
  world::World world = world::loadWorld(yaml);
  world.robot().initial_pose = {-12.0, 0.0, 0.0};  // in the offices on the left
  planAndReport(state, world);
}
BENCHMARK(BM_CoveragePlanWillowFull)->Unit(benchmark::kMillisecond)->Iterations(1);

// The touch-up a robot plans once it has driven all the rows of the whole office floor (the
// floor its disc swept along every leg, marked every 5 mm): roomba_bt stands still while it is
// planned. Its transits to places no search can reach used to explore the whole floor: 23-39 s
// in a real run; see FreeSpace::shortestPath.
void BM_CoverageTouchUpWillowFull(benchmark::State& state) {
  const std::string yaml = ROOMBA_RRT_SHARED_MAPS "/willow_full.yaml";
  if (!std::filesystem::exists(yaml)) {
    state.SkipWithError(("no " + yaml).c_str());
    return;
  }
  const world::World world = world::loadWorld(yaml);
  const coverage::CoveragePlanner planner(world, coverage::cleaningOptions(world));
  const coverage::CoveragePlan plan = planner.plan({-12.0, 0.0});
  std::vector<std::uint8_t> swept;
  for (const coverage::Leg& leg : plan.legs) {
    for (std::size_t s = 0; s + 1 < leg.points.size(); ++s) {
      const coverage::Point2 a = leg.points[s], b = leg.points[s + 1];
      const int n = 1 + static_cast<int>(std::hypot(b.x - a.x, b.y - a.y) / 0.005);
      for (int k = 0; k <= n; ++k) {
        const double t = double(k) / n;
        planner.markSwept(swept, {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
      }
    }
  }
  coverage::CoveragePlan touch_up;
  for (auto _ : state) {
    touch_up = planner.touchUp(swept, plan.legs.back().points.back(), 0.012);
    benchmark::DoNotOptimize(touch_up.legs.data());
  }
  state.counters["legs"] = static_cast<double>(touch_up.legs.size());
}
BENCHMARK(BM_CoverageTouchUpWillowFull)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
