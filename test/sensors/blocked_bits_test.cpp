// The map's blocked cells as bits (blocked_bits.h): every bit, the border's included, against
// OccupancyGrid::blocked on random grids whose sides are not multiples of 8, along both axes.
#include <gtest/gtest.h>

#include <random>

#include "roomba_rrt/sensors/blocked_bits.h"

namespace roomba_rrt::sensors {
namespace {

using geometry::OccupancyGrid;

OccupancyGrid randomGrid(std::mt19937& rng) {
  std::uniform_int_distribution<int> side(1, 75), value(0, 9);
  OccupancyGrid g;
  g.width = side(rng);
  g.height = side(rng);
  g.resolution = 0.05;
  g.cells.resize(static_cast<std::size_t>(g.width) * g.height);
  for (auto& c : g.cells) {
    const int v = value(rng);
    c = v < 2 ? OccupancyGrid::kOccupied : (v < 3 ? OccupancyGrid::kUnknown : OccupancyGrid::kFree);
  }
  return g;
}

/// Every bit of `bits` (lines of cells along x when `along_x`) is the grid's cell, blocked beyond
/// the grid; and runs of up to 57 cells read as those bits.
void expectCells(const OccupancyGrid& g, const BlockedBits& bits, bool along_x, std::mt19937& rng) {
  ASSERT_EQ(bits.lines(), along_x ? g.height : g.width);
  ASSERT_EQ(bits.length(), along_x ? g.width : g.height);
  for (int v = -BlockedBits::kPadLines; v < bits.lines() + BlockedBits::kPadLines; ++v) {
    for (int u = -BlockedBits::kPadCells; u < bits.length() + BlockedBits::kPadCells; ++u) {
      const bool blocked = along_x ? g.blocked(u, v) : g.blocked(v, u);
      ASSERT_EQ(BlockedBits::blocked(bits.line(v), u), blocked) << "cell " << u << " of line " << v;
    }
  }
  std::uniform_int_distribution<int> line(-BlockedBits::kPadLines,
                                          bits.lines() + BlockedBits::kPadLines - 1);
  std::uniform_int_distribution<int> start(-BlockedBits::kPadCells,
                                           bits.length() + BlockedBits::kPadCells - 1);
  for (int k = 0; k < 200; ++k) {
    const int v = line(rng), u = start(rng);
    const int n = std::min(1 + static_cast<int>(rng() % 57), bits.length() + 8 - u);
    const std::uint64_t run = BlockedBits::cells(bits.line(v), u, n);
    for (int b = 0; b < 64; ++b) {
      const bool expected = b < n && BlockedBits::blocked(bits.line(v), u + b);
      ASSERT_EQ((run >> b) & 1, expected) << "bit " << b << " of " << n << " from " << u;
    }
  }
}

TEST(BlockedBits, every_cell_and_the_border_along_rows_and_columns) {
  std::mt19937 rng(3);
  for (int m = 0; m < 60; ++m) {
    const OccupancyGrid g = randomGrid(rng);
    SCOPED_TRACE(::testing::Message() << "grid " << m << ": " << g.width << " x " << g.height);
    const BlockedBits rows(g);
    expectCells(g, rows, true, rng);
    expectCells(g, rows.transposed(), false, rng);
  }
}

}  // namespace
}  // namespace roomba_rrt::sensors
