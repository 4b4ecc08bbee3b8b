// The free-space sampler on maps: points drawn from the map's free tiles, uniform over the free
// points, and found where the map's rectangle is almost all unknown.
#include "roomba_rrt/planning/free_space_sampler.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "../geometry/text_grid.h"
#include "roomba_rrt/planning/problem.h"

namespace roomba_rrt::planning {
namespace {

/// A 200 × 200 map of unknown cells (0.1 m) with an L of free floor: a 20 × 10 bar (x 1-3 m,
/// y 1-2 m) and a 10 × 10 block above its left end (x 1-2, y 2-3); the L is 0.03 of the map.
std::shared_ptr<const geometry::OccupancyGrid> lMap() {
  std::vector<std::string> rows(200, std::string(200, '?'));
  for (int j = 10; j < 30; ++j) {
    for (int i = 10; i < (j < 20 ? 30 : 20); ++i) rows[199 - j][i] = '.';
  }
  return std::make_shared<const geometry::OccupancyGrid>(geometry::text_grid::gridFrom(rows));
}

TEST(FreeTiles, lists_every_tile_holding_a_free_cell_and_no_other) {
  const auto grid = lMap();
  const geometry::FreeTiles tiles(*grid, false);
  // The L's cells 10..29 × 10..19 and 10..19 × 20..29 touch the 8 × 8-cell tiles 1..3 × 1..2
  // and 1..2 × 2..3: eight tiles.
  static_assert(geometry::FreeTiles::kCells == 8);
  EXPECT_EQ(tiles.size(), 8u);
  EXPECT_DOUBLE_EQ(tiles.area(), 8 * 0.8 * 0.8);
  EXPECT_EQ(geometry::FreeTiles(*grid, true).size(), 25u * 25u);  // unknown counts as free
}

TEST(FreeSpaceSampler, on_a_mostly_unknown_map_finds_free_points_in_few_draws) {
  Problem problem = mapProblem(lMap());
  const CollisionChecker checker = collisionChecker(problem, CollisionCheck::kSegments);
  // The L is 3 % of the rectangle: 20 draws in the rectangle find it in under half the runs;
  // drawn from the free tiles (59 % of whose area is the L), every run does.
  const FreeSpaceSampler sampler(problem.bounds, checker, 20);
  MatlabRandom random(7);
  for (int n = 0; n < 1000; ++n) {
    const std::optional<Point2> p = sampler.sample(random);
    ASSERT_TRUE(p.has_value()) << "sample " << n;
    EXPECT_TRUE(checker.isFree(*p));
  }
}

TEST(FreeSpaceSampler, draws_from_tiles_uniformly_over_the_free_points) {
  Problem problem = mapProblem(lMap());
  const CollisionChecker checker = collisionChecker(problem, CollisionCheck::kSegments);
  const FreeSpaceSampler sampler(problem.bounds, checker, 1000);
  MatlabRandom random(11);
  // The bar holds 2/3 of the L's area, the block 1/3; within the bar, x is uniform on [1, 3].
  constexpr int kSamples = 30000;
  int in_block = 0;
  double bar_x = 0;
  for (int n = 0; n < kSamples; ++n) {
    const Point2 p = *sampler.sample(random);
    if (p.y > 2) {
      ++in_block;
    } else {
      bar_x += p.x;
    }
  }
  const double block_share = static_cast<double>(in_block) / kSamples;
  EXPECT_NEAR(block_share, 1.0 / 3, 0.01);  // about 3.7 standard deviations
  EXPECT_NEAR(bar_x / (kSamples - in_block), 2.0, 0.02);
}

TEST(FreeSpaceSampler, keeps_to_bounds_smaller_than_the_map) {
  Problem problem = mapProblem(lMap());
  const CollisionChecker checker = collisionChecker(problem, CollisionCheck::kSegments);
  // Right of x = 2: larger than the free tiles, so drawn from them, but only the bar's right half
  // of the L is inside.
  const Bounds right{2.0, 20.0, 0.0, 20.0};
  const FreeSpaceSampler sampler(right, checker, 1000);
  MatlabRandom random(3);
  for (int n = 0; n < 1000; ++n) {
    const Point2 p = *sampler.sample(random);
    ASSERT_TRUE(contains(right, p) && p.y < 2) << p.x << ", " << p.y;
  }
}

}  // namespace
}  // namespace roomba_rrt::planning
