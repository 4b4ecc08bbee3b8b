// The boustrophedon decomposition, its rows and the order they are swept in, each on its own
// (coverage_planner_test plans whole rooms with them).
#include "roomba_rrt/coverage/boustrophedon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <optional>
#include <vector>

#include "roomba_rrt/coverage/cell_order.h"
#include "roomba_rrt/coverage/coverage_planner.h"
#include "roomba_rrt/world/world.h"
#include "roomba_rrt/world/world_file.h"

using roomba_rrt::coverage::Cell;
using roomba_rrt::coverage::cellRows;
using roomba_rrt::coverage::CellVisit;
using roomba_rrt::coverage::CoverageOptions;
using roomba_rrt::coverage::decompose;
using roomba_rrt::coverage::flood;
using roomba_rrt::coverage::FreeSpace;
using roomba_rrt::coverage::kMinStepWidth;
using roomba_rrt::coverage::kWays;
using roomba_rrt::coverage::Mask;
using roomba_rrt::coverage::orderCells;
using roomba_rrt::coverage::pruneRows;
using roomba_rrt::coverage::Row;
using roomba_rrt::coverage::Sweep;
using roomba_rrt::coverage::sweepRows;
using roomba_rrt::coverage::Sweeps;
using roomba_rrt::coverage::Way;
using roomba_rrt::geometry::Point2;
using roomba_rrt::geometry::Rectangle;
using roomba_rrt::world::World;

namespace {

/// The lab's empty 6.4 m × 4.8 m room with the 0.17 m Roomba (config/roomba_world.yaml).
World emptyRoom() {
  return roomba_rrt::world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world.yaml");
}

/// The free space the planner samples, and its kFree points connected to (x, y).
struct Sampled {
  explicit Sampled(const World& world, double x = 1.0, double y = 1.0)
      : space(world, CoverageOptions{}.clearance, CoverageOptions{}.resolution) {
    const std::optional<int> seed = space.connect({x, y}, FreeSpace::kFree);
    region = seed ? flood(space, *seed, FreeSpace::kFree) : Mask(space.size(), 0);
  }
  FreeSpace space;
  Mask region;
};

/// How many lattice points the cells' slices hold.
int slicePoints(const std::vector<Cell>& cells) {
  int n = 0;
  for (const Cell& cell : cells) {
    for (const auto& slice : cell) n += slice.b - slice.a + 1;
  }
  return n;
}

/// Every cell is a stack of slices, one per lattice row, consecutive, each overlapping the one
/// below it: a shape horizontal rows sweep without leaving it.
void expectStacks(const std::vector<Cell>& cells) {
  for (std::size_t c = 0; c < cells.size(); ++c) {
    for (std::size_t k = 1; k < cells[c].size(); ++k) {
      const auto &below = cells[c][k - 1], &here = cells[c][k];
      EXPECT_EQ(here.j, below.j + 1) << "cell " << c << " slice " << k;
      EXPECT_TRUE(here.a <= below.b && below.a <= here.b) << "cell " << c << " slice " << k;
    }
  }
}

TEST(Boustrophedon, an_empty_room_is_one_cell_of_all_its_free_points) {
  const Sampled s(emptyRoom());
  const std::vector<Cell> cells = decompose(s.space, s.region);
  ASSERT_EQ(cells.size(), 1u);
  EXPECT_EQ(slicePoints(cells), std::count(s.region.begin(), s.region.end(), 1));
  expectStacks(cells);
}

TEST(Boustrophedon, a_table_in_the_middle_splits_the_room_into_four_cells) {
  World world = emptyRoom();
  world.room.rectangles.push_back(Rectangle{2.5, 1.8, 3.9, 3.0});
  const Sampled s(world);
  const std::vector<Cell> cells = decompose(s.space, s.region);
  // Below the table, left and right of it (the sweep line meets it: a split), above it (the two
  // join again).
  ASSERT_EQ(cells.size(), 4u);
  EXPECT_EQ(slicePoints(cells), std::count(s.region.begin(), s.region.end(), 1));
  expectStacks(cells);
  const double h = s.space.resolution();
  auto top = [&](const Cell& cell) { return s.space.point(0, cell.back().j).y; };
  auto bottom = [&](const Cell& cell) { return s.space.point(0, cell.front().j).y; };
  // The two beside the table span its height grown by the planning radius.
  const double grown = s.space.planningRadius();
  int beside = 0;
  for (const Cell& cell : cells) {
    if (std::fabs(bottom(cell) - (1.8 - grown)) < 2 * h &&
        std::fabs(top(cell) - (3.0 + grown)) < 2 * h) {
      ++beside;
    }
  }
  EXPECT_EQ(beside, 2);
}

TEST(Boustrophedon, an_l_shaped_room_narrows_but_stays_one_cell_with_a_row_along_its_step) {
  World world = emptyRoom();
  world.room.rectangles.push_back(Rectangle{3.2, 2.4, 6.4, 4.8});  // the upper right quarter
  const Sampled s(world);
  const std::vector<Cell> cells = decompose(s.space, s.region);
  ASSERT_EQ(cells.size(), 1u);  // each lattice row meets the L in one interval
  const std::vector<Row> rows = cellRows(s.space, cells[0], CoverageOptions{}.swath);
  // The step is 3.2 m wide (more than kMinStepWidth): a row runs along it, under the walled-off
  // quarter, from the L's inner corner to the wall, at the planning radius below the step.
  ASSERT_GT(3.2, kMinStepWidth);
  const double under_step = 2.4 - s.space.planningRadius();
  const bool along_step = std::any_of(rows.begin(), rows.end(), [&](const Row& row) {
    return std::fabs(row.left.y - under_step) < 1e-3 && row.left.x > 2.9 && row.left.x < 3.2 &&
           row.right.x > 6.4 - s.space.planningRadius() - 1e-3;
  });
  EXPECT_TRUE(along_step);
}

TEST(Boustrophedon, rows_are_at_most_a_swath_apart_and_the_outer_ones_at_the_planning_radius) {
  const World world = emptyRoom();
  const Sampled s(world);
  const std::vector<Cell> cells = decompose(s.space, s.region);
  ASSERT_EQ(cells.size(), 1u);
  const double swath = CoverageOptions{}.swath, R = s.space.planningRadius();
  const std::vector<Row> rows = cellRows(s.space, cells[0], swath);
  // 4.8 m less twice the planning radius, in as few gaps of at most a swath as there can be.
  const double span = world.room.height - 2 * R;
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(std::ceil(span / swath)) + 1);
  EXPECT_NEAR(rows.front().left.y, R, 1e-3);
  EXPECT_NEAR(rows.back().left.y, world.room.height - R, 1e-3);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_EQ(rows[k].left.y, rows[k].right.y) << "row " << k << " is not along x";
    EXPECT_NEAR(rows[k].left.x, R, 1e-3) << "row " << k;
    EXPECT_NEAR(rows[k].right.x, world.room.width - R, 1e-3) << "row " << k;
    EXPECT_TRUE(s.space.segmentFree(rows[k].left, rows[k].right)) << "row " << k;
    if (k > 0) {
      EXPECT_LE(rows[k].left.y - rows[k - 1].left.y, swath + 1e-9) << "row " << k;
    }
  }
}

TEST(Boustrophedon, pruning_drops_rows_another_row_already_sweeps_and_keeps_the_rest) {
  const Sampled s(emptyRoom());
  const std::vector<Cell> cells = decompose(s.space, s.region);
  const std::vector<Row> rows = cellRows(s.space, cells[0], CoverageOptions{}.swath);
  Mask floor(s.space.size());
  for (int k = 0; k < s.space.size(); ++k) floor[k] = s.space.isFloor(k);
  // The same rows twice (two cells that overlap completely): one copy of each is enough.
  std::vector<std::vector<Row>> twice{rows, rows};
  pruneRows(s.space, floor, twice);
  EXPECT_EQ(twice[0].size() + twice[1].size(), rows.size());
  // Alone, every row sweeps floor no other does: all are kept, each within its own segment and
  // at most trimmed at its ends to the last floor it alone reaches (less than a lattice step).
  std::vector<std::vector<Row>> once{rows};
  pruneRows(s.space, floor, once);
  ASSERT_EQ(once[0].size(), rows.size());
  const double h = s.space.resolution();
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_GE(once[0][k].left.x, rows[k].left.x) << "row " << k;
    EXPECT_LT(once[0][k].left.x, rows[k].left.x + h) << "row " << k;
    EXPECT_LE(once[0][k].right.x, rows[k].right.x) << "row " << k;
    EXPECT_GT(once[0][k].right.x, rows[k].right.x - h) << "row " << k;
  }
}

TEST(CellOrder, rows_alternate_in_the_way_asked_so_each_starts_where_the_last_ended) {
  const std::vector<Row> rows{{{0, 0}, {4, 0}}, {{0, 0.3}, {4, 0.3}}, {{0, 0.6}, {4, 0.6}}};
  const Sweep up = sweepRows(rows, Way{true, true});
  ASSERT_EQ(up.size(), 3u);
  EXPECT_EQ(up[0].first.x, 0);  // left to right, from the lowest
  EXPECT_EQ(up[0].first.y, 0);
  EXPECT_EQ(up[1].first.x, 4);  // back, one row up
  EXPECT_EQ(up[1].first.y, 0.3);
  EXPECT_EQ(up[2].first.x, 0);
  const Sweep down = sweepRows(rows, Way{false, false});
  EXPECT_EQ(down[0].first.x, 4);  // right to left, from the highest
  EXPECT_EQ(down[0].first.y, 0.6);
  EXPECT_EQ(down[2].second.x, 0);
}

TEST(CellOrder, a_short_row_is_entered_from_its_nearer_end_and_the_rows_after_it_still_alternate) {
  // A 0.5 m row at the right end between two long ones (a step's row).
  const std::vector<Row> rows{{{0, 0}, {4, 0}}, {{3.5, 0.3}, {4, 0.3}}, {{0, 0.6}, {4, 0.6}}};
  const Sweep up = sweepRows(rows, Way{true, true});
  ASSERT_EQ(up.size(), 3u);
  // Out along the first to x = 4; the short row there, whichever way; then the third from x = 4
  // back: the jumps add up to the two 0.3 m steps and the short row's length, not a drive across.
  double jumps = 0;
  for (std::size_t k = 1; k < up.size(); ++k) {
    jumps += std::hypot(up[k].first.x - up[k - 1].second.x, up[k].first.y - up[k - 1].second.y);
  }
  EXPECT_LT(jumps, 0.3 + 0.3 + 0.5 + 1e-9);
  EXPECT_EQ(up[2].second.x, 0);
}

TEST(CellOrder, cells_are_swept_from_the_nearest_on_and_each_enters_where_the_last_left) {
  // Three cells along x, 2 m apart, each one row; the robot starts by the rightmost.
  std::vector<std::vector<Row>> rows{{{{0, 0}, {1, 0}}}, {{{3, 0}, {4, 0}}}, {{{6, 0}, {7, 0}}}};
  Sweeps sweeps(rows.size());
  for (std::size_t c = 0; c < rows.size(); ++c) {
    for (std::size_t w = 0; w < std::size(kWays); ++w) sweeps[c][w] = sweepRows(rows[c], kWays[w]);
  }
  const std::vector<CellVisit> order = orderCells(sweeps, {7.5, 0});
  ASSERT_EQ(order.size(), 3u);
  EXPECT_EQ(order[0].cell, 2u);
  EXPECT_EQ(order[1].cell, 1u);
  EXPECT_EQ(order[2].cell, 0u);
  for (const CellVisit& v : order) {  // each row right to left: the jumps are the 2 m gaps
    const auto& row = sweeps[v.cell][v.way].front();
    EXPECT_GT(row.first.x, row.second.x) << "cell " << v.cell;
  }
}

}  // namespace
