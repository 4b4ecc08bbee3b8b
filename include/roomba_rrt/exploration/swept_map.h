// The map a robot without a range finder builds of a home it has never seen: the floor its disc
// has swept (free for certain: it was there), the points its bumper and IR light bumper found on
// obstacles (occupied, for good), and everything else unknown. ROS-free. The classic Roomba's
// cleaning (bump_clean.h, online_boustrophedon.h) plans on it.
//
// Cells are small squares on a lattice whose cell (0, 0) is centred on the robot's start; the map
// grows as the robot goes. A cell is
//   - swept when its centre has been inside the robot's disc (the rule of the simulator's
//     coverage grid, sim/coverage_grid.h),
//   - occupied when it holds a point found on an obstacle; the points themselves are kept, so
//     that how far the robot may drive is measured from them, not from the cells' squares,
//   - blocked when the robot's disc centred on it comes within reach() (radius + clearance) of
//     such a point: a centre the robot never plans through.
// Occupied and blocked never go back: a robot that cannot see cannot tell a chair that moved from
// one it missed.
#pragma once

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "roomba_rrt/geometry/geometry.h"
#include "roomba_rrt/geometry/occupancy_grid.h"

namespace roomba_rrt::exploration {

/// A cell of the map's lattice: column i, row j, cell (0, 0) centred on the start.
struct Cell {
  int i = 0, j = 0;
  bool operator==(const Cell& o) const { return i == o.i && j == o.j; }
};

class SweptMap {
 public:
  /// For a disc robot of `radius` that keeps `clearance` from every point it has found, starting
  /// at `start`, on cells of `resolution` (m), first 2 m round the start.
  SweptMap(const geometry::Point2& start, double radius, double clearance,
           double resolution = 0.025);

  /// The robot's disc stands at `centre`: every cell whose centre lies in it is swept, and the
  /// cell holding `centre` visited.
  void sweep(const geometry::Point2& centre);
  /// A point on an obstacle (an IR return, a bump): its cell is occupied and every centre within
  /// reach() of it blocked. A point within 5 mm of one already kept adds nothing.
  void markObstacle(const geometry::Point2& p);

  double resolution() const { return resolution_; }
  double radius() const { return radius_; }
  /// How near a point on an obstacle the robot's centre may come: radius + clearance.
  double reach() const { return reach_; }

  Cell cellOf(const geometry::Point2& p) const;
  geometry::Point2 centre(const Cell& c) const {
    return {start_.x + c.i * resolution_, start_.y + c.j * resolution_};
  }
  bool swept(const Cell& c) const { return flags(c) & kSwept; }
  bool occupied(const Cell& c) const { return flags(c) & kOccupied; }
  bool blocked(const Cell& c) const { return flags(c) & kBlocked; }
  /// Neither swept nor occupied.
  bool unknown(const Cell& c) const { return !(flags(c) & (kSwept | kOccupied)); }
  /// The robot's centre has been in it: the robot can stand there (whatever it found since
  /// within reach: it passed between two obstacles with less than the clearance to spare, or a
  /// bump was placed a little off where it was).
  bool visited(const Cell& c) const { return flags(c) & kVisited; }

  /// How far (m, at most `max`) the robot's centre can go from `from` along the unit vector
  /// `direction` before its disc comes within reach() of a point found on an obstacle: 0 when one
  /// ahead of it already is. Exact against the points, whatever the cells.
  double freeLength(const geometry::Point2& from, const geometry::Point2& direction,
                    double max) const;

  /// The cells held: columns [minColumn(), minColumn() + columns()), rows likewise. Every cell
  /// outside is unknown.
  int minColumn() const { return i0_; }
  int minRow() const { return j0_; }
  int columns() const { return width_; }
  int rows() const { return height_; }
  long sweptCells() const { return swept_count_; }
  std::size_t obstaclePoints() const { return point_count_; }
  /// Every point found on an obstacle (for tests and pictures; a copy).
  std::vector<geometry::Point2> points() const;
  /// Calls `visit(point)` for the points found on obstacles in the cells that overlap the
  /// rectangle [lo, hi] (some may lie a cell outside it).
  template <class Visit>
  void forPointsNear(const geometry::Point2& lo, const geometry::Point2& hi, Visit visit) const {
    const Cell a = cellOf(lo), b = cellOf(hi);
    for (int j = std::max(a.j, j0_); j <= std::min(b.j, j0_ + height_ - 1); ++j) {
      for (int i = std::max(a.i, i0_); i <= std::min(b.i, i0_ + width_ - 1); ++i) {
        if (!(flags({i, j}) & kOccupied)) continue;
        for (const geometry::Point2& q : points_.at(key({i, j}))) visit(q);
      }
    }
  }

  /// As nav_msgs/OccupancyGrid means it, over the cells held: swept cells free (0), occupied ones
  /// 100, the rest unknown (−1). What roomba_bt could publish, and what the tests look at.
  geometry::OccupancyGrid grid() const;

 private:
  static constexpr std::uint8_t kSwept = 1, kOccupied = 2, kBlocked = 4, kVisited = 8;
  std::uint8_t flags(const Cell& c) const {
    const int i = c.i - i0_, j = c.j - j0_;
    if (i < 0 || j < 0 || i >= width_ || j >= height_) return 0;
    return flags_[static_cast<std::size_t>(j) * width_ + i];
  }
  std::uint8_t& at(const Cell& c) {
    return flags_[static_cast<std::size_t>(c.j - j0_) * width_ + (c.i - i0_)];
  }
  /// Grows the cells held (by a metre beyond) to take in columns [i_lo, i_hi] and rows [j_lo,
  /// j_hi].
  void hold(int i_lo, int j_lo, int i_hi, int j_hi);
  static std::int64_t key(const Cell& c) {
    return (static_cast<std::int64_t>(c.i) << 32) ^ (static_cast<std::int64_t>(c.j) & 0xffffffff);
  }

  geometry::Point2 start_;
  double radius_, reach_, resolution_;
  int i0_ = 0, j0_ = 0, width_ = 0, height_ = 0;
  std::vector<std::uint8_t> flags_;
  long swept_count_ = 0;
  /// The points found on obstacles, by the cell holding them.
  std::unordered_map<std::int64_t, std::vector<geometry::Point2>> points_;
  std::size_t point_count_ = 0;
};

}  // namespace roomba_rrt::exploration
