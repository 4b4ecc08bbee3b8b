#include "roomba_rrt/sim/coverage_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using roomba_rrt::sim::CoverageGrid;
using roomba_rrt::world::World;

TEST(CoverageGrid, covers_the_room_with_cells_of_the_configured_size) {
  const CoverageGrid grid{World{}};
  EXPECT_EQ(grid.columns(), 256);  // 6.4 m / 0.025 m
  EXPECT_EQ(grid.rows(), 192);     // 4.8 m / 0.025 m
  EXPECT_EQ(grid.freeCells(), 256 * 192);
  EXPECT_EQ(grid.coverage(), 0.0);
}

TEST(CoverageGrid, furniture_is_not_free_floor) {
  World world;
  world.room.rectangles = {{0.0, 0.0, 1.0, 1.0}};
  const CoverageGrid grid{world};
  EXPECT_EQ(grid.freeCells(), 256 * 192 - 40 * 40);
  EXPECT_FALSE(grid.isFree(10, 10));
  EXPECT_TRUE(grid.isFree(41, 10));
}

TEST(CoverageGrid, a_disc_marks_its_area_and_marking_twice_counts_once) {
  CoverageGrid grid{World{}};
  grid.markDisc(3.2, 2.4, 0.17);
  const long cells = grid.sweptFreeCells();
  EXPECT_NEAR(cells * 0.025 * 0.025, M_PI * 0.17 * 0.17, 0.025 * 2 * M_PI * 0.17 / 2);
  grid.markDisc(3.2, 2.4, 0.17);
  EXPECT_EQ(grid.sweptFreeCells(), cells);
  EXPECT_TRUE(grid.isSwept(128, 96));
  grid.clear();
  EXPECT_EQ(grid.sweptFreeCells(), 0);
  EXPECT_FALSE(grid.isSwept(128, 96));
}

TEST(CoverageGrid, swept_furniture_cells_do_not_count) {
  World world;
  world.room.circles = {{3.2, 2.4, 0.1}};
  CoverageGrid grid{world};
  grid.markDisc(3.2, 2.4, 0.5);
  CoverageGrid empty{World{}};
  empty.markDisc(3.2, 2.4, 0.5);
  EXPECT_EQ(empty.sweptFreeCells() - grid.sweptFreeCells(), empty.freeCells() - grid.freeCells());
}

TEST(CoverageGrid, discs_at_the_edge_of_the_room_stay_inside_the_grid) {
  CoverageGrid grid{World{}};
  grid.markDisc(0.0, 0.0, 0.17);
  grid.markDisc(6.4, 4.8, 0.17);
  EXPECT_GT(grid.sweptFreeCells(), 0);
  EXPECT_LT(grid.coverage(), 0.01);
}

TEST(CoverageGrid, discs_far_outside_or_not_finite_mark_nothing) {
  CoverageGrid grid{World{}};
  grid.markDisc(1e12, -1e12, 0.17);
  grid.markDisc(std::nan(""), 2.0, 0.17);
  grid.markDisc(3.0, 2.0, std::numeric_limits<double>::infinity());
  EXPECT_EQ(grid.sweptFreeCells(), 0);
}
