// Boustrophedon cellular decomposition (Choset & Pignon, 1997) of the free space of the disc's
// centre on a lattice, and the back-and-forth rows that cover each cell. ROS-free.
//
// A line sweeps up the lattice, row by row. In each lattice row the free points form intervals
// (slices). A slice that overlaps exactly one slice of the row below, which overlaps only it,
// continues that slice's cell; any other (the line meets an obstacle, two parts of the free
// space join, or one splits) opens a new cell. A cell is thus a stack of slices, one per lattice
// row, without holes: horizontal rows cover it without leaving it. The rows keep the planning
// radius from everything exactly: the lattice's free points are joined by provably free edges,
// and every row moved off the lattice (out to the walls) is tested (FreeSpace::segmentFree).
// CoveragePlanner (coverage_planner.h) orders the cells (cell_order.h) and joins their rows.
#pragma once

#include <vector>

#include "roomba_rrt/coverage/free_space.h"

namespace roomba_rrt::coverage {

/// The shortest row pruneRows() leaves (m), unless the free space is shorter: a row that must only
/// reach a spot still has a direction for the follower to drive in.
constexpr double kMinRowLength = 0.05;

/// A cell that widens or narrows by this much (m) from one lattice row to the next gets a row
/// along the step (cellRows): the strip of up to a swath beside a narrower step is not worth the
/// U-turns and the transit to it. 0.4 m: the 0.8 m sideboard of the furnished room gets one; 1 m
/// left an 0.8 m × 0.2 m strip unswept there.
constexpr double kMinStepWidth = 0.4;

/// A row that would sweep less floor than this (m²) that no other row sweeps is not planned: a
/// spot of a few square centimetres is not worth a transit and two turns.
constexpr double kMinRowGain = 0.01;

/// Floor only one row sweeps comes in bunches along it (pruneRows): lattice columns of it further
/// apart than this (m) are in different bunches, and a bunch of less than kMinRowGain is not worth
/// driving the row to. Two cells that meet each have a row along where they meet, a few
/// centimetres apart; the one pruned first sweeps slivers of its own beyond the other's ends,
/// which are not worth keeping the whole stretch between them for.
constexpr double kBunchGap = 0.6;

/// One lattice row's stretch of a cell: columns a..b of lattice row j.
struct Slice {
  int j = 0;
  int a = 0;
  int b = 0;
};

/// A cell of the decomposition: one slice per lattice row, bottom to top, consecutive rows.
using Cell = std::vector<Slice>;

/// Boustrophedon decomposition of `region`, swept from the lowest lattice row up. A slice
/// continues the cell of the one slice below it that it overlaps, when that slice overlaps
/// nothing else above; otherwise (an obstacle splits the free space, two parts of it join, or
/// the free space begins) it opens a new cell.
std::vector<Cell> decompose(const FreeSpace& space, const Mask& region);

/// A cleaning row: a horizontal segment from `left` to `right` (left.x ≤ right.x).
struct Row {
  Point2 left;
  Point2 right;
};

/// The rows of `cell`, bottom to top. Some are fixed: along its lowest and its highest slice (so
/// the disc brushes what bounds the cell below and above), moved out as far as they stay free
/// (the lattice stops up to a step short of the walls), and along the wider slice beside every
/// place where the cell widens or narrows by kMinStepWidth or more from one lattice row to the
/// next (it passes the top or reaches the bottom of something beside it: a sideboard against the
/// wall), so that the floor beside the step's narrow side is swept. Between two fixed rows the
/// others are evenly spaced, at any height, as few as keep neighbours at most `swath` apart. Each
/// row's ends are then moved out as far as they stay free (exactly).
std::vector<Row> cellRows(const FreeSpace& space, const Cell& cell, double swath);

/// Removes the rows whose floor other rows sweep as well, and shortens the others to the stretch
/// that sweeps floor no other row does (keptStretch). Cells overlap where they meet (each has its
/// lowest and highest row), and thin cells between nearby events (the tops of two pieces of
/// furniture) are mostly swept by their neighbours' rows; this drops that double work, losing
/// no floor but bunches of less than kMinRowGain that only one row would sweep. Rows with the
/// least floor of their own go first; every row stays inside its original segment, so it stays
/// free. `floor` marks the floor to sweep (the reachable floor).
void pruneRows(const FreeSpace& space, const Mask& floor, std::vector<std::vector<Row>>& cells);

}  // namespace roomba_rrt::coverage
