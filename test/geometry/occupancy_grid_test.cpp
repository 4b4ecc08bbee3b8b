// The grid's exact disc queries against brute force over every cell's square, and the places
// where a disc robot meets a map: a one-cell gap, a wall's corner, the map's edge.
#include "roomba_rrt/geometry/occupancy_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "text_grid.h"

namespace roomba_rrt::geometry {
namespace {

using text_grid::bruteDistance;
using text_grid::gridFrom;

TEST(OccupancyGrid, cells_are_row_major_from_the_bottom_and_squares_tile_the_extent) {
  const OccupancyGrid grid = gridFrom({"#..", "..?"}, 0.5, {-1.0, 2.0});
  EXPECT_EQ(grid.at(0, 1), OccupancyGrid::kOccupied);  // top-left of the picture
  EXPECT_EQ(grid.at(2, 0), OccupancyGrid::kUnknown);   // bottom-right
  const Rectangle s = grid.square(2, 1);
  EXPECT_DOUBLE_EQ(s.min_x, 0.0);
  EXPECT_DOUBLE_EQ(s.max_y, 3.0);
  EXPECT_EQ(grid.column(-1.0), 0);
  EXPECT_EQ(grid.column(-1.01), -1);
  EXPECT_EQ(grid.row(2.99), 1);
  EXPECT_TRUE(grid.blocked(2, 0));
  EXPECT_FALSE(grid.blocked(2, 0, /*unknown_is_free=*/true));
  EXPECT_TRUE(grid.blocked(-1, 0));  // the map's edge is a wall
  EXPECT_TRUE(grid.blocked(0, 2));
  EXPECT_FALSE(grid.blocked(1, 1));
}

TEST(OccupancyGrid, the_known_extent_is_what_was_mapped_without_the_unknown_border) {
  const OccupancyGrid grid = gridFrom({"??????",  //
                                       "???#??",  //
                                       "?#..??",  //
                                       "??.???",  //
                                       "??????"},
                                      0.5, {-1.0, 2.0});
  const Rectangle known = grid.knownExtent();  // columns 1..3, rows 1..3 from the bottom
  EXPECT_DOUBLE_EQ(known.min_x, -0.5);
  EXPECT_DOUBLE_EQ(known.max_x, 1.0);
  EXPECT_DOUBLE_EQ(known.min_y, 2.5);
  EXPECT_DOUBLE_EQ(known.max_y, 4.0);
  const OccupancyGrid unknown = gridFrom({"???", "???"}, 0.5, {-1.0, 2.0});
  const Rectangle all = unknown.knownExtent();  // nothing mapped: the whole grid
  EXPECT_DOUBLE_EQ(all.min_x, -1.0);
  EXPECT_DOUBLE_EQ(all.max_x, 0.5);
  EXPECT_DOUBLE_EQ(all.min_y, 2.0);
  EXPECT_DOUBLE_EQ(all.max_y, 3.0);
  const Rectangle whole = gridFrom({"#.", ".."}).knownExtent();
  EXPECT_DOUBLE_EQ(whole.max_x, 0.2);
  EXPECT_DOUBLE_EQ(whole.max_y, 0.2);
}

TEST(OccupancyGrid, distance_to_blocked_equals_brute_force_over_every_square) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> cell(0, 9);
  for (int trial = 0; trial < 20; ++trial) {
    OccupancyGrid grid =
        gridFrom(std::vector<std::string>(12, std::string(15, '.')), 0.05, {-0.3, 0.2});
    for (auto& c : grid.cells) {
      const int r = cell(rng);
      c = r == 0 ? OccupancyGrid::kOccupied : r == 1 ? OccupancyGrid::kUnknown : c;
    }
    std::uniform_real_distribution<double> x(-0.4, 0.5), y(0.1, 0.9);
    for (int k = 0; k < 200; ++k) {
      const Point2 p{x(rng), y(rng)};
      for (const bool unknown_is_free : {false, true}) {
        const double reach = 0.2;
        const double expected = std::min(reach, bruteDistance(grid, p, unknown_is_free));
        ASSERT_NEAR(distanceToBlocked(grid, p, reach, unknown_is_free), expected, 1e-12)
            << "p = (" << p.x << ", " << p.y << ")";
        ASSERT_EQ(blockedWithin(grid, p, reach, unknown_is_free),
                  distanceToBlocked(grid, p, reach, unknown_is_free) < reach);
        for (const double radius : {0.01, 0.05, 0.12}) {
          ASSERT_EQ(discMeetsBlocked(grid, p, radius, unknown_is_free),
                    bruteDistance(grid, p, unknown_is_free) <= radius);
        }
      }
    }
  }
}

TEST(OccupancyGrid, a_disc_passes_a_one_cell_gap_only_when_narrower_than_it) {
  // A wall with a one-cell (0.1 m) doorway in the middle column.
  const OccupancyGrid grid = gridFrom({".....", ".....", "##.##", ".....", "....."});
  const Point2 door{0.25, 0.25};  // the doorway's centre
  EXPECT_FALSE(discMeetsBlocked(grid, door, 0.049));
  EXPECT_TRUE(discMeetsBlocked(grid, door, 0.05));  // touching the door posts counts
  EXPECT_DOUBLE_EQ(distanceToBlocked(grid, door, 1.0), 0.05);
}

TEST(OccupancyGrid, near_a_corner_the_distance_is_to_the_corner_point) {
  const OccupancyGrid grid = gridFrom({"....", "....", "#...", "...."});
  // Cell (0, 1) spans [0, 0.1] x [0.1, 0.2]; its upper-right corner is (0.1, 0.2).
  const Point2 p{0.13, 0.24};
  EXPECT_NEAR(distanceToBlocked(grid, p, 1.0), std::hypot(0.03, 0.04), 1e-12);
  std::vector<Rectangle> near;
  blockedSquaresNear(grid, p, 0.051, near);
  ASSERT_EQ(near.size(), 1u);
  EXPECT_DOUBLE_EQ(near[0].max_y, 0.2);
}

}  // namespace
}  // namespace roomba_rrt::geometry
