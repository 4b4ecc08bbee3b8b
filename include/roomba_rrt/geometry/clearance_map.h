// A map inflated for a disc robot: may a disc of radius r stand at p, or slide from a to b,
// without touching an occupied or unknown cell? Exact against every blocked cell's square (the
// geometry the simulator bumps against), fast because a distance transform settles most cells
// without looking at a square.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "roomba_rrt/geometry/free_tiles.h"
#include "roomba_rrt/geometry/geometry.h"
#include "roomba_rrt/geometry/occupancy_grid.h"

namespace roomba_rrt::geometry {

/// Built once per map (the distance transform of its blocked cells, distance_transform.h), then
/// asked for discs of any radius, from any number of threads.
///
/// A disc is free when it lies inside the map's extent and has no point in common with a
/// blocked cell's closed square: distance from its centre to every blocked square > radius
/// (touching is a collision, as for the planner's circles and rectangles). Each query first looks
/// at the cells the centre (or the segment) passes through. With d the distance in cells from a
/// cell's centre to the nearest blocked cell's centre and k = radius / resolution:
///   - d − √2 > k: every point of the cell is farther than the radius from every blocked square
///     (no point of a cell is more than √2/2 cells from its centre, nor of a square from its
///     centre): free, nothing more to look at;
///   - d + √2/2 < k (or the cell is blocked): every point of the cell is within the radius of the
///     nearest blocked cell's centre, which its square contains: blocked;
///   - otherwise, a band about two cells wide along the inflated walls: the exact distance to the
///     blocked squares within the radius of the cell, among the blocked cells that have a free
///     neighbour (the nearest point of a union of squares lies on such a cell's square).
class ClearanceMap {
 public:
  /// Thresholds of one radius, computed once (see disc()).
  struct Disc {
    double radius = 0;
    double radius_sq = 0;
    double free_above = 0;     ///< squared cell distance above which a cell is free
    double blocked_below = 0;  ///< squared cell distance below which a cell is blocked
    int reach_cells = 1;       ///< cells around a cell whose squares may come within the radius
  };

  /// `unknown_is_free`: unknown cells (−1) are free floor instead of walls (~allow_unknown).
  explicit ClearanceMap(std::shared_ptr<const OccupancyGrid> grid, bool unknown_is_free = false);

  const OccupancyGrid& grid() const { return *grid_; }
  /// The tiles holding a free cell, where a sampler draws points (built with the map).
  const FreeTiles& freeTiles() const { return free_tiles_; }
  bool unknownIsFree() const { return unknown_is_free_; }
  Disc disc(double radius) const;

  /// True when the closed disc around p is inside the map and meets no blocked square.
  bool discFree(const Point2& p, const Disc& disc) const;
  /// True when the disc sliding along the segment a-b (every disc centred on it) is inside the
  /// map and meets no blocked square: the segment keeps the radius from every blocked square.
  bool sweepFree(const Point2& a, const Point2& b, const Disc& disc) const;

  /// The distance transform's value of cell (i, j): squared cells from its centre to the nearest
  /// blocked cell's centre; 0 for a blocked cell with a free neighbour, −1 for a blocked cell
  /// without one (inside a wall).
  std::int32_t squaredCellDistance(int i, int j) const {
    return distance_[static_cast<std::size_t>(j) * grid_->width + i];
  }
  /// Memory held per cell beyond the grid's own byte: the distance transform's 4 bytes.
  static constexpr std::size_t kBytesPerCell = sizeof(std::int32_t);

 private:
  enum class Cell { kFree, kBlocked, kNear };
  Cell classify(int i, int j, const Disc& disc) const;
  bool insideExtent(const Point2& p, double radius) const;
  /// True when the distance transform at the segment's midpoint alone proves the sweep free.
  bool clearAroundMidpoint(const Point2& a, const Point2& b, const Disc& disc) const;
  /// The exact sweep: the cells the segment passes through, and the squares near those in the band.
  bool exactSweepFree(const Point2& a, const Point2& b, const Disc& disc) const;
  /// Calls visit(i, j) for every cell the segment a-b passes through (and any within kWalkSlack of
  /// it), column by column, until it returns false; false if it did.
  template <class Visit>
  bool forEachCellOnSegment(const Point2& a, const Point2& b, Visit visit) const;
  /// Whether hit(i, j) holds for a blocked cell beside a free one among columns [i0, i1] × rows
  /// [j0, j1] (clipped to the grid).
  template <class Hit>
  bool anySquare(int i0, int i1, int j0, int j1, Hit hit) const;

  std::shared_ptr<const OccupancyGrid> grid_;
  bool unknown_is_free_;
  std::vector<std::int32_t> distance_;
  FreeTiles free_tiles_;
};

// Inline: every query asks them, and calls within a shared library are not inlined otherwise.

inline ClearanceMap::Cell ClearanceMap::classify(int i, int j, const Disc& disc) const {
  const double d = squaredCellDistance(i, j);
  if (d <= 0 || d < disc.blocked_below) return Cell::kBlocked;
  return d > disc.free_above ? Cell::kFree : Cell::kNear;
}

inline bool ClearanceMap::insideExtent(const Point2& p, double radius) const {
  const Rectangle e = grid_->extent();
  return p.x - radius > e.min_x && p.x + radius < e.max_x && p.y - radius > e.min_y &&
         p.y + radius < e.max_y;
}

inline bool ClearanceMap::clearAroundMidpoint(const Point2& a, const Point2& b,
                                              const Disc& disc) const {
  // Every point of the segment is within half its length h of the midpoint m. With d the cells
  // from m's cell's centre to the nearest blocked centre, every blocked square is farther than
  // d − √2 cells from m (m is within √2/2 of its cell's centre, a square's points within √2/2 of
  // its own), so the sweep is free when d − √2 > (h + radius) / resolution. Moved by a relative
  // 1e-9 towards "sweep exactly", as disc(): rounding never certifies a step it should not.
  const Point2 m{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
  // Inside the extent (both ends are), so inside the grid (clamped for rounding on its last edge).
  const int i = std::min(grid_->column(m.x), grid_->width - 1);
  const int j = std::min(grid_->row(m.y), grid_->height - 1);
  const double d_sq = squaredCellDistance(i, j);
  const double need = (0.5 * distance(a, b) + disc.radius) / grid_->resolution + std::sqrt(2.0);
  return d_sq > need * need * (1 + 1e-9) + 1e-9;
}

}  // namespace roomba_rrt::geometry
