// The A* peer of the map benchmark (bench/grid_astar.h): a wrong peer makes wrong rows, so its
// path is checked against a case worked out by hand and against the exact disc tests.
#include "grid_astar.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "../geometry/text_grid.h"

namespace roomba_rrt::bench {
namespace {

using geometry::ClearanceMap;
using geometry::OccupancyGrid;
using geometry::Point2;

constexpr double kRadius = 0.17;  // m: 1.7 cells of 0.1 m
constexpr double kCell = 0.1;

/// 15 × 11 cells of 0.1 m with a wall up column 7 from the bottom edge to row 4 (rows count from
/// the bottom). Inflated by 1.7 cells: the disc's centre keeps to cells 2..12 × 2..8 (the map's
/// edge is a wall) and passes the wall only in rows 7 and 8 of columns 6..8, rows 6..8 of columns
/// 5 and 9 (a cell two columns and two rows off the wall's corner is 2.12 cells from it).
std::shared_ptr<const OccupancyGrid> wallGrid(bool with_gap = true) {
  std::vector<std::string> rows(11, std::string(15, '.'));
  for (int j = 0; j <= (with_gap ? 4 : 10); ++j) rows[10 - j][7] = '#';
  return std::make_shared<const OccupancyGrid>(geometry::text_grid::gridFrom(rows, kCell));
}

Point2 cellCentre(int i, int j) { return {(i + 0.5) * kCell, (j + 0.5) * kCell}; }

TEST(GridAStar, TheShortestEightConnectedPathAroundAWallHasTheLengthWorkedOutByHand) {
  const ClearanceMap map(wallGrid());
  const GridAStar astar(map, kRadius);
  const GridAStar::Result r = astar.plan(cellCentre(2, 2), cellCentre(12, 2));
  ASSERT_FALSE(r.path.empty());
  // Over the wall through column 6 and 8 at row ≥ 7: from (2, 2) to (6, 7) at least the octile
  // distance of (4, 5), 4 diagonals and 1 straight; 2 straight steps to (8, 7); the same down to
  // (12, 2); and (2,2) (3,3) (4,4) (4,5) (5,6) (6,7) (7,7) (8,7) ... reaches that bound.
  const double expected = (8 * std::sqrt(2.0) + 4) * kCell;
  EXPECT_NEAR(r.length, expected, 1e-9);
  EXPECT_NEAR(geometry::pathLength(r.path), expected, 1e-9);
  EXPECT_NEAR(r.path.front().x, cellCentre(2, 2).x, 1e-12);
  EXPECT_NEAR(r.path.back().x, cellCentre(12, 2).x, 1e-12);
}

TEST(GridAStar, EveryStepIsANeighbourMoveTheDiscSweepsFreely) {
  const ClearanceMap map(wallGrid());
  const ClearanceMap::Disc disc = map.disc(kRadius);
  const GridAStar astar(map, kRadius);
  const GridAStar::Result r = astar.plan(cellCentre(12, 8), cellCentre(2, 3));
  ASSERT_GE(r.path.size(), 2u);
  for (std::size_t k = 0; k + 1 < r.path.size(); ++k) {
    const Point2 &a = r.path[k], &b = r.path[k + 1];
    EXPECT_LE(std::max(std::abs(a.x - b.x), std::abs(a.y - b.y)), kCell + 1e-12) << k;
    EXPECT_TRUE(map.sweepFree(a, b, disc)) << "step " << k;
    // The exact distance to every blocked square, by brute force, keeps the radius.
    for (double t : {0.0, 0.25, 0.5, 0.75}) {
      const Point2 p{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
      EXPECT_GT(geometry::text_grid::bruteDistance(map.grid(), p, false), kRadius) << k;
    }
  }
}

TEST(GridAStar, NoPathWhereTheWallCutsTheMapOrAnEndIsInIt) {
  const ClearanceMap closed(wallGrid(false));
  EXPECT_TRUE(GridAStar(closed, kRadius).plan(cellCentre(2, 2), cellCentre(12, 2)).path.empty());
  const ClearanceMap open(wallGrid());
  const GridAStar astar(open, kRadius);
  EXPECT_TRUE(astar.plan(cellCentre(6, 3), cellCentre(12, 2)).path.empty());  // beside the wall
  EXPECT_TRUE(astar.plan({-1, 0.5}, cellCentre(12, 2)).path.empty());         // off the map
}

}  // namespace
}  // namespace roomba_rrt::bench
