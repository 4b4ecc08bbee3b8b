// The order a coverage plan sweeps the cells of its decomposition (boustrophedon.h) in, and the
// order and direction it drives each cell's rows in: short straight jumps between rows and
// between cells, a lower bound of the transits that join them. ROS-free.
#pragma once

#include <array>
#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

#include "roomba_rrt/coverage/boustrophedon.h"

namespace roomba_rrt::coverage {

/// At most this many improvements of the cell order (each moves one cell): enough to settle a
/// room's few dozen cells, and a bound on the work in a large map.
constexpr int kMaxOrderRounds = 200;

/// One of the four ways to sweep a cell's rows: upwards or downwards, the first row from left to
/// right or from right to left; the rows then alternate.
struct Way {
  bool upwards = true;
  bool first_left_to_right = true;
};
constexpr Way kWays[] = {{true, true}, {true, false}, {false, true}, {false, false}};

/// A cell's rows in the order they are driven, each as (start, end).
using Sweep = std::vector<std::pair<Point2, Point2>>;

/// The rows of a cell as `way` sweeps them: the first row in the way's direction, then the others
/// in the directions that make the straight jumps between rows shortest (dynamic programming over
/// the two directions of each row), and in the order of their heights but where driving two
/// neighbours the other way round makes the jumps shorter. Rows alternate, but a short row (a
/// step's, or one pruneRows() shortened) would flip the alternation of all the rows after it:
/// it is entered from its nearer end, after the row before or the row after it, whichever
/// leaves the robot where the next row starts. Ties keep the alternation.
Sweep sweepRows(const std::vector<Row>& rows, Way way);

/// A cell in the sweep order, and the way it is swept.
struct CellVisit {
  std::size_t cell = 0;
  std::size_t way = 0;  ///< index in kWays
};

/// sweeps[c][w]: cell c swept the way kWays[w].
using Sweeps = std::vector<std::array<Sweep, std::size(kWays)>>;

/// The order to sweep the cells with rows in: first greedily (from where the robot is, the cell
/// whose first row starts nearest), then improved by moving single cells to another place in the
/// order or sweeping them another way, while that shortens the straight jumps between cells (a
/// lower bound of the transits), at most kMaxOrderRounds times.
std::vector<CellVisit> orderCells(const Sweeps& sweeps, const Point2& start);

}  // namespace roomba_rrt::coverage
