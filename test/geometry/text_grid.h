// Occupancy grids for tests, drawn as text, and the brute-force distance the exact queries are
// checked against.
#pragma once

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "roomba_rrt/geometry/geometry.h"
#include "roomba_rrt/geometry/occupancy_grid.h"

namespace roomba_rrt::geometry::text_grid {

/// A grid from rows of text, top row first as in an image: '#' occupied, '?' unknown, '.' free.
inline OccupancyGrid gridFrom(const std::vector<std::string>& rows, double resolution = 0.1,
                              Point2 origin = {0, 0}) {
  OccupancyGrid grid;
  grid.width = static_cast<int>(rows[0].size());
  grid.height = static_cast<int>(rows.size());
  grid.resolution = resolution;
  grid.origin = origin;
  grid.cells.resize(static_cast<std::size_t>(grid.width) * grid.height);
  for (int j = 0; j < grid.height; ++j) {
    for (int i = 0; i < grid.width; ++i) {
      const char c = rows[grid.height - 1 - j][i];
      grid.cells[j * grid.width + i] = c == '#'   ? OccupancyGrid::kOccupied
                                       : c == '?' ? OccupancyGrid::kUnknown
                                                  : OccupancyGrid::kFree;
    }
  }
  return grid;
}

/// Distance from `p` to the nearest blocked square by brute force: every blocked cell, and the
/// outside of the map (a wall beyond its edge).
inline double bruteDistance(const OccupancyGrid& grid, const Point2& p, bool unknown_is_free) {
  const Rectangle e = grid.extent();
  double best = 0;
  if (contains(e, p)) best = std::min({p.x - e.min_x, e.max_x - p.x, p.y - e.min_y, e.max_y - p.y});
  for (int j = 0; j < grid.height; ++j) {
    for (int i = 0; i < grid.width; ++i) {
      if (grid.blocked(i, j, unknown_is_free)) {
        best = std::min(best, distance(grid.square(i, j), p));
      }
    }
  }
  return best;
}

}  // namespace roomba_rrt::geometry::text_grid
