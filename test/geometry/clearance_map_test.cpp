// The distance transform and the inflated map's disc queries against brute force over every
// blocked cell's square, on random grids and radii, and the places a disc robot meets a map.
#include "roomba_rrt/geometry/clearance_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "roomba_rrt/geometry/distance_transform.h"
#include "text_grid.h"

namespace roomba_rrt::geometry {
namespace {

using text_grid::bruteDistance;
using text_grid::gridFrom;

/// A random grid: each cell occupied with probability `density`, unknown with a third of it.
std::shared_ptr<OccupancyGrid> randomGrid(std::mt19937& rng, int width, int height,
                                          double density) {
  auto grid = std::make_shared<OccupancyGrid>();
  grid->width = width;
  grid->height = height;
  grid->resolution = 0.05;
  grid->origin = {-0.3, 1.1};
  std::uniform_real_distribution<double> u(0, 1);
  for (int c = 0; c < width * height; ++c) {
    const double x = u(rng);
    grid->cells.push_back(x < density           ? OccupancyGrid::kOccupied
                          : x < density * 4 / 3 ? OccupancyGrid::kUnknown
                                                : OccupancyGrid::kFree);
  }
  return grid;
}

/// Distance from the segment to the nearest blocked square, by brute force (the map's edge is
/// checked by the caller through the ends).
double bruteSegmentDistance(const OccupancyGrid& grid, const Segment& s, bool unknown_is_free) {
  double best = std::numeric_limits<double>::infinity();
  for (int j = 0; j < grid.height; ++j) {
    for (int i = 0; i < grid.width; ++i) {
      if (grid.blocked(i, j, unknown_is_free)) {
        best = std::min(best, distance(grid.square(i, j), s));
      }
    }
  }
  return best;
}

bool insideBy(const OccupancyGrid& grid, const Point2& p, double radius) {
  const Rectangle e = grid.extent();
  return p.x - radius > e.min_x && p.x + radius < e.max_x && p.y - radius > e.min_y &&
         p.y + radius < e.max_y;
}

TEST(DistanceTransform, is_the_squared_distance_to_the_nearest_blocked_centre) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 40; ++trial) {
    const bool unknown_is_free = trial % 2 == 1;
    const auto grid = randomGrid(rng, 1 + trial % 23, 1 + (trial * 7) % 19, 0.02 + 0.01 * trial);
    const std::vector<std::int32_t> d = squaredDistanceTransform(*grid, unknown_is_free);
    for (int j = 0; j < grid->height; ++j) {
      for (int i = 0; i < grid->width; ++i) {
        std::int64_t best = kNoBlockedCell;
        for (int l = 0; l < grid->height; ++l) {
          for (int k = 0; k < grid->width; ++k) {
            if (grid->blocked(k, l, unknown_is_free)) {
              best = std::min<std::int64_t>(best, (i - k) * (i - k) + (j - l) * (j - l));
            }
          }
        }
        ASSERT_EQ(d[j * grid->width + i], best) << "trial " << trial << " cell " << i << "," << j;
      }
    }
  }
}

TEST(DistanceTransform, a_grid_without_blocked_cells_is_far_everywhere) {
  const OccupancyGrid grid = gridFrom({"...", "..?"});
  EXPECT_EQ(squaredDistanceTransform(grid, true), std::vector<std::int32_t>(6, kNoBlockedCell));
  EXPECT_EQ(squaredDistanceTransform(grid, false)[0], 4);  // (0, 0) is 2 cells from (2, 0)
}

TEST(ClearanceMap, marks_the_cells_inside_walls_and_keeps_the_walls_faces) {
  const ClearanceMap map(std::make_shared<OccupancyGrid>(gridFrom({"###.", "###.", "###."})));
  EXPECT_EQ(map.squaredCellDistance(0, 1), -1);  // blocked all round (the edge counts)
  EXPECT_EQ(map.squaredCellDistance(1, 1), -1);
  EXPECT_EQ(map.squaredCellDistance(2, 1), 0);  // beside the free column
  EXPECT_EQ(map.squaredCellDistance(3, 1), 1);
}

TEST(ClearanceMap, disc_queries_agree_with_brute_force) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  int free = 0, blocked = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const bool unknown_is_free = trial % 3 == 0;
    const auto grid = randomGrid(rng, 20 + trial, 25, 0.01 + 0.004 * trial);
    const ClearanceMap map(grid, unknown_is_free);
    const Rectangle e = grid->extent();
    for (double radius : {0.0, 0.02, 0.05, 0.17, 0.3}) {
      const ClearanceMap::Disc disc = map.disc(radius);
      for (int n = 0; n < 300; ++n) {
        const Point2 p{e.min_x + u(rng) * (e.max_x - e.min_x),
                       e.min_y + u(rng) * (e.max_y - e.min_y)};
        const double d = bruteDistance(*grid, p, unknown_is_free);
        if (std::abs(d - radius) < 1e-9) continue;  // on the rim: rounding decides
        const bool expected = d > radius && insideBy(*grid, p, radius);
        ASSERT_EQ(map.discFree(p, disc), expected)
            << "trial " << trial << " radius " << radius << " at " << p.x << "," << p.y;
        (expected ? free : blocked)++;
      }
    }
  }
  EXPECT_GT(free, 5000);  // both answers were exercised
  EXPECT_GT(blocked, 5000);
}

TEST(ClearanceMap, sweep_queries_agree_with_brute_force) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0, 1);
  int free = 0, blocked = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const bool unknown_is_free = trial % 3 == 1;
    const auto grid = randomGrid(rng, 30, 20 + trial, 0.003 + 0.002 * trial);
    const ClearanceMap map(grid, unknown_is_free);
    const Rectangle e = grid->extent();
    for (double radius : {0.0, 0.03, 0.17, 0.25}) {
      const ClearanceMap::Disc disc = map.disc(radius);
      for (int n = 0; n < 200; ++n) {
        const Point2 a{e.min_x + u(rng) * (e.max_x - e.min_x),
                       e.min_y + u(rng) * (e.max_y - e.min_y)};
        // Lengths from a fraction of a cell to across the map; some axis-parallel.
        const double length = 0.01 * std::pow(150.0, u(rng)), angle = u(rng) * 2 * M_PI;
        Point2 b{a.x + length * std::cos(angle), a.y + length * std::sin(angle)};
        if (n % 10 == 0) b.x = a.x;
        if (n % 10 == 1) b.y = a.y;
        const Segment s{a, b};
        const double d = bruteSegmentDistance(*grid, s, unknown_is_free);
        if (std::abs(d - radius) < 1e-9) continue;
        const bool expected =
            d > radius && insideBy(*grid, a, radius) && insideBy(*grid, b, radius);
        ASSERT_EQ(map.sweepFree(a, b, disc), expected)
            << "trial " << trial << " radius " << radius << " from " << a.x << "," << a.y << " to "
            << b.x << "," << b.y;
        // The plain check of tools and tests, away from the map's edge (beyond it: blocked).
        if (insideBy(*grid, a, radius) && insideBy(*grid, b, radius)) {
          ASSERT_EQ(segmentMeetsBlocked(*grid, s, radius, unknown_is_free), d <= radius);
        }
        (expected ? free : blocked)++;
      }
    }
  }
  EXPECT_GT(free, 2000);
  EXPECT_GT(blocked, 2000);
}

TEST(ClearanceMap, long_sweeps_along_a_wall_agree_with_brute_force) {
  // Steps of 60 to 180 cells running beside a straight wall, about a radius from it: their cells
  // lie in the band along the wall, more of them than the sweep keeps from its first walk.
  auto grid = std::make_shared<OccupancyGrid>();
  grid->width = 200;
  grid->height = 40;
  grid->resolution = 0.05;
  grid->origin = {-0.3, 1.1};
  grid->cells.assign(200 * 40, OccupancyGrid::kFree);
  for (int i = 0; i < 200; ++i) grid->cells[10 * 200 + i] = OccupancyGrid::kOccupied;
  grid->cells[10 * 200 + 150] = OccupancyGrid::kFree;     // a notch in the wall
  grid->cells[11 * 200 + 70] = OccupancyGrid::kOccupied;  // a bump on it
  const ClearanceMap map(grid);
  const double wall_top = grid->origin.y + 11 * grid->resolution;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  int free = 0, blocked = 0;
  for (double radius : {0.12, 0.17}) {
    const ClearanceMap::Disc disc = map.disc(radius);
    for (int n = 0; n < 300; ++n) {
      const double length = 3 + 6 * u(rng);
      const double x0 = grid->origin.x + 0.3 + u(rng) * (9.4 - length);
      const Point2 a{x0, wall_top + radius + (u(rng) - 0.4) * 0.1};
      const Point2 b{x0 + length, a.y + (u(rng) - 0.5) * 0.05};
      const double d = bruteSegmentDistance(*grid, {a, b}, false);
      if (std::abs(d - radius) < 1e-9) continue;
      ASSERT_EQ(map.sweepFree(a, b, disc), d > radius)
          << "radius " << radius << " from " << a.x << "," << a.y << " to " << b.x << "," << b.y;
      (d > radius ? free : blocked)++;
    }
  }
  EXPECT_GT(free, 100);
  EXPECT_GT(blocked, 100);
}

TEST(ClearanceMap, a_disc_passes_a_gap_wider_than_it_and_not_a_narrower_one) {
  // A wall across the map with a gap three cells (0.3 m) wide.
  auto grid = std::make_shared<OccupancyGrid>(gridFrom({
      "..........",
      "..........",
      "..........",
      "###...####",
      "..........",
      "..........",
      "..........",
  }));
  const ClearanceMap map(grid);
  const Point2 below{0.45, 0.15}, above{0.45, 0.55};
  EXPECT_TRUE(map.sweepFree(below, above, map.disc(0.14)));   // 0.28 m wide
  EXPECT_FALSE(map.sweepFree(below, above, map.disc(0.15)));  // 0.30 m: touches both sides
  EXPECT_FALSE(map.sweepFree(below, above, map.disc(0.17)));  // the Roomba
  // Along the gap's axis the disc clears the wall's corners only when it is narrower.
  EXPECT_FALSE(map.discFree({0.45, 0.35}, map.disc(0.151)));
  EXPECT_TRUE(map.discFree({0.45, 0.35}, map.disc(0.149)));
}

TEST(ClearanceMap, a_diagonal_between_two_corners_touching_is_blocked) {
  // Two blocked cells meeting at one corner: a point robot cannot slip between them.
  auto grid = std::make_shared<OccupancyGrid>(gridFrom({"...", ".#.", "#..", "..."}));
  const ClearanceMap map(grid);
  const ClearanceMap::Disc point = map.disc(0);
  EXPECT_FALSE(map.sweepFree({0.05, 0.25}, {0.25, 0.15}, point));  // through the shared corner
  EXPECT_TRUE(map.sweepFree({0.05, 0.35}, {0.25, 0.35}, point));   // above both
}

}  // namespace
}  // namespace roomba_rrt::geometry
