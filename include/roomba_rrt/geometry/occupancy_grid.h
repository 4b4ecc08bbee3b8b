// An occupancy grid, the map every ROS user has (map_server, SLAM, nav_msgs/OccupancyGrid), and
// the exact questions a disc robot asks of it: is the disc clear of every blocked cell's square,
// and how far is the nearest one. ROS-free; map_file.h reads one from a map_server YAML.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "roomba_rrt/geometry/geometry.h"

namespace roomba_rrt::geometry {

/// Cells in rows, row 0 at the bottom (lowest y), as nav_msgs/OccupancyGrid holds them: cell
/// (i, j) (column i, row j) is the square [x0 + i·r, x0 + (i + 1)·r] × [y0 + j·r, y0 + (j + 1)·r]
/// with r = resolution and (x0, y0) = origin, its value at cells[j · width + i]: kFree (0),
/// kOccupied (100) or kUnknown (−1), the values map_server publishes in its trinary mode.
struct OccupancyGrid {
  static constexpr std::int8_t kFree = 0;
  static constexpr std::int8_t kOccupied = 100;
  static constexpr std::int8_t kUnknown = -1;

  int width = 0;          ///< cells along x
  int height = 0;         ///< cells along y
  double resolution = 0;  ///< edge of a cell, m
  Point2 origin;          ///< the lower-left corner of cell (0, 0), m
  std::vector<std::int8_t> cells;

  std::int8_t at(int i, int j) const { return cells[static_cast<std::size_t>(j) * width + i]; }
  bool inside(int i, int j) const { return i >= 0 && j >= 0 && i < width && j < height; }
  /// Whether a robot may not be on cell (i, j): any value but kFree (occupied, unknown unless
  /// `unknown_is_free`, a probability from another source), or outside the grid (the map's edge
  /// is a wall).
  bool blocked(int i, int j, bool unknown_is_free = false) const {
    return !inside(i, j) || blockedValue(at(i, j), unknown_is_free);
  }
  /// The same rule for a cell's value alone (a cell known to be inside the grid).
  static bool blockedValue(std::int8_t v, bool unknown_is_free = false) {
    return v != kFree && !(v == kUnknown && unknown_is_free);
  }
  /// The closed square of cell (i, j).
  Rectangle square(int i, int j) const {
    return {origin.x + i * resolution, origin.y + j * resolution, origin.x + (i + 1) * resolution,
            origin.y + (j + 1) * resolution};
  }
  /// The whole map's rectangle.
  Rectangle extent() const {
    return {origin.x, origin.y, origin.x + width * resolution, origin.y + height * resolution};
  }
  /// The rectangle of the cells that are known (free or occupied): what was mapped, without the
  /// unknown border a SLAM map has round it (gmapping's 4000 × 4000 cells for a flat). The whole
  /// extent when no cell is known.
  Rectangle knownExtent() const;
  /// The column and row holding `p` (possibly outside the grid: negative or ≥ width / height).
  int column(double x) const { return static_cast<int>(std::floor((x - origin.x) / resolution)); }
  int row(double y) const { return static_cast<int>(std::floor((y - origin.y) / resolution)); }
};

/// Distance from `p` to the nearest blocked cell's square (0 inside one), searched within
/// `reach` of p: `reach` itself when no blocked square is nearer. Exact (closest point of each
/// square), cells outside the grid count as blocked. Cost: the cells within reach.
double distanceToBlocked(const OccupancyGrid& grid, const Point2& p, double reach,
                         bool unknown_is_free = false);

/// Whether distanceToBlocked(grid, p, reach) < reach: a blocked square lies nearer than `reach`
/// to p. The same answer, but it stops at the first such square: a lattice of a large robot on
/// a map is mostly blocked points, each of which used to cost every cell within reach (a 1.6 m
/// robot on the apartment map took 25 s to sample under the sanitizers).
bool blockedWithin(const OccupancyGrid& grid, const Point2& p, double reach,
                   bool unknown_is_free = false);

/// Whether the closed disc of `radius` around `p` has a point in common with a blocked cell's
/// square (touching counts), i.e. distanceToBlocked(p) ≤ radius.
bool discMeetsBlocked(const OccupancyGrid& grid, const Point2& p, double radius,
                      bool unknown_is_free = false);

/// Whether the segment comes within `margin` of a blocked cell's square (touching counts): exact
/// (the segment-rectangle distance of each square), cells outside the grid count as blocked.
/// Cost: the cells of the segment's column bands grown by the margin, column by column — a plain
/// check for tools, the coverage planner and tests; the planner's fast one is
/// ClearanceMap::sweepFree.
bool segmentMeetsBlocked(const OccupancyGrid& grid, const Segment& segment, double margin,
                         bool unknown_is_free = false);

/// The blocked cells' squares that come within `radius` of `p`, for contact: the point of each
/// square closest to p (the direction of the push-back and of the bumper switch). Appends to
/// `out` (cleared first).
void blockedSquaresNear(const OccupancyGrid& grid, const Point2& p, double radius,
                        std::vector<Rectangle>& out, bool unknown_is_free = false);

}  // namespace roomba_rrt::geometry
