// Plans on the real maps of ../shared/maps: 1000 seeded start/goal pairs over the five maps and
// the three algorithms, in both collision modes, every edge of every path checked against the
// map's blocked squares independently of the planner's own checker (the grid and plain
// segment-rectangle distances, no distance transform).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <queue>
#include <random>
#include <string>
#include <vector>

#include "../common/shared_maps.h"
#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/planning/lab/scenarios.h"
#include "roomba_rrt/planning/planner.h"

namespace roomba_rrt::planning {
namespace {

using geometry::OccupancyGrid;

constexpr double kRoomba = 0.17;

/// The centres of the cells a Roomba can stand on and reach from each other (4-neighbours whose
/// centres both keep the radius), largest such region: where the pairs are drawn.
std::vector<Point2> largestRegion(const Problem& problem) {
  const OccupancyGrid& g = problem.map->grid();
  const geometry::ClearanceMap::Disc disc = problem.map->disc(kRoomba);
  auto centre = [&](int i, int j) {
    return Point2{g.origin.x + (i + 0.5) * g.resolution, g.origin.y + (j + 0.5) * g.resolution};
  };
  std::vector<int> label(g.cells.size(), -1);
  std::vector<Point2> best;
  for (int start = 0; start < static_cast<int>(g.cells.size()); ++start) {
    if (label[start] >= 0 || !problem.map->discFree(centre(start % g.width, start / g.width), disc))
      continue;
    std::vector<Point2> region;
    std::queue<int> open;
    open.push(start);
    label[start] = start;
    while (!open.empty()) {
      const int c = open.front();
      open.pop();
      const int i = c % g.width, j = c / g.width;
      region.push_back(centre(i, j));
      for (auto [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const int n = (j + dj) * g.width + (i + di);
        if (!g.inside(i + di, j + dj) || label[n] >= 0) continue;
        if (!problem.map->discFree(centre(i + di, j + dj), disc)) continue;
        label[n] = start;
        open.push(n);
      }
    }
    if (region.size() > best.size()) best = std::move(region);
  }
  return best;
}

struct MapCase {
  const char* name;
  int plans;
};

TEST(MapPlanning, every_edge_of_1000_seeded_plans_keeps_the_radius_from_every_blocked_square) {
  int total = 0, found = 0;
  for (const MapCase& m :
       {MapCase{"turtlebot3_world", 250}, MapCase{"depot", 200}, MapCase{"warehouse", 200},
        MapCase{"willow_full", 200}, MapCase{"nav2_bench_100by100_15", 150}}) {
    ROOMBA_RRT_REQUIRE_SHARED_MAP(m.name);
    const std::string file = ::roomba_rrt::test::sharedMapPath(m.name);
    auto grid = std::make_shared<OccupancyGrid>(geometry::loadMap(file).grid);
    Problem problem = mapProblem(grid);
    problem.robot_radius = kRoomba;
    const std::vector<Point2> region = largestRegion(problem);
    ASSERT_GT(region.size(), 1000u) << m.name;
    std::mt19937 rng(17);
    std::uniform_int_distribution<std::size_t> pick(0, region.size() - 1);
    int map_found = 0;
    double seconds[3] = {0, 0, 0};
    for (int n = 0; n < m.plans; ++n) {
      problem.start = region[pick(rng)];
      do {
        problem.goal = region[pick(rng)];
      } while (distance(problem.start, problem.goal) < 1.0);
      PlannerOptions options;
      options.seed = 1000 + n;
      options.algorithm = n % 3 == 0   ? Algorithm::kRrt
                          : n % 3 == 1 ? Algorithm::kRrtConnect
                                       : Algorithm::kRrtStar;
      options.collision = n % 2 == 0 ? CollisionCheck::kPoints : CollisionCheck::kSegments;
      options.step = 1.0;
      options.goal_bias = 0.05;
      options.goal_tolerance = 0.05;
      options.max_iterations = options.algorithm == Algorithm::kRrtStar ? 4000 : 100000;
      options.smooth = n % 4 == 3;
      // Half from each stream: the fast one is what the service plans maps with.
      options.random_stream = (n / 6) % 2 == 0 ? RandomStream::kMatlab : RandomStream::kFast;
      const PlanResult result = plan(problem, options);
      ++total;
      seconds[n % 3] += result.planning_time;
      if (!result.success) continue;
      ++map_found, ++found;
      ASSERT_GE(result.path.size(), 2u);
      EXPECT_EQ(result.path.front().x, problem.start.x);
      for (std::size_t k = 1; k < result.path.size(); ++k) {
        const Segment edge{result.path[k - 1], result.path[k]};
        ASSERT_FALSE(geometry::segmentMeetsBlocked(*grid, edge, kRoomba))
            << m.name << " plan " << n << " edge " << k << " (" << edge.a.x << ", " << edge.a.y
            << ") - (" << edge.b.x << ", " << edge.b.y << ")";
      }
    }
    std::printf("%s: %d of %d paths found (%.2f s rrt, %.2f s rrt_connect, %.2f s rrt_star)\n",
                m.name, map_found, m.plans, seconds[0], seconds[1], seconds[2]);
    // Most pairs of one region are joined within the iterations (RRT* with fewer).
    EXPECT_GE(map_found, m.plans * 7 / 10) << m.name;
  }
  EXPECT_EQ(total, 1000);
  RecordProperty("paths_found", found);
}

TEST(MapPlanning, the_inflated_maps_sweeps_agree_with_the_plain_exact_check_on_real_maps) {
  // Steps from a fraction of a cell to 3 m between points where the Roomba is free: most are
  // settled by the distance transform at their midpoint, the rest by the exact sweep.
  for (const char* name :
       {"turtlebot3_world", "depot", "warehouse", "willow_full", "nav2_bench_100by100_15"}) {
    ROOMBA_RRT_REQUIRE_SHARED_MAP(name);
    auto grid = std::make_shared<OccupancyGrid>(
        geometry::loadMap(::roomba_rrt::test::sharedMapPath(name)).grid);
    const geometry::ClearanceMap map(grid);
    const geometry::ClearanceMap::Disc disc = map.disc(kRoomba);
    const geometry::Rectangle e = grid->extent();
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(0, 1);
    int free = 0, blocked = 0;
    while (free + blocked < 20000) {
      const Point2 a{e.min_x + u(rng) * (e.max_x - e.min_x),
                     e.min_y + u(rng) * (e.max_y - e.min_y)};
      // Half from a fraction of a cell to 2 m (log-uniform), half up to 3 m (uniform).
      const double length = (free + blocked) % 2 ? 0.005 * std::pow(400.0, u(rng)) : 3 * u(rng);
      const double angle = u(rng) * 2 * M_PI;
      const Point2 b{a.x + length * std::cos(angle), a.y + length * std::sin(angle)};
      if (!map.discFree(a, disc) || !map.discFree(b, disc)) continue;  // ends inside, free
      const bool expected = !geometry::segmentMeetsBlocked(*grid, {a, b}, kRoomba);
      ASSERT_EQ(map.sweepFree(a, b, disc), expected)
          << name << " from " << a.x << "," << a.y << " to " << b.x << "," << b.y;
      (expected ? free : blocked)++;
    }
    EXPECT_GT(free, 5000) << name;  // both answers exercised
    EXPECT_GT(blocked, 50) << name;
  }
}

TEST(MapPlanning, a_start_or_goal_in_a_wall_is_refused_naming_it) {
  ROOMBA_RRT_REQUIRE_SHARED_MAP("turtlebot3_world");
  auto grid = std::make_shared<OccupancyGrid>(
      geometry::loadMap(::roomba_rrt::test::sharedMapPath("turtlebot3_world")).grid);
  Problem problem = mapProblem(grid);
  problem.robot_radius = kRoomba;
  problem.start = {-2.0, -0.5};   // free floor of the arena
  problem.goal = {-20.0, -20.0};  // outside the map
  EXPECT_NE(plan(problem, {}).message.find("goal"), std::string::npos);
  problem.goal = {-8.0, -8.0};  // unknown, beyond the arena's wall
  const PlanResult unknown = plan(problem, {});
  EXPECT_FALSE(unknown.success);
  EXPECT_NE(unknown.message.find("goal: (-8, -8) is in a wall of the map"), std::string::npos)
      << unknown.message;
  // Unknown cells allowed: the same goal is open floor (if the unknown region reaches it).
  Problem open = mapProblem(grid, /*allow_unknown=*/true);
  open.robot_radius = kRoomba;
  open.start = problem.start;
  open.goal = problem.goal;
  EXPECT_EQ(plan(open, {}).message.find("in a wall"), std::string::npos);
}

}  // namespace
}  // namespace roomba_rrt::planning
