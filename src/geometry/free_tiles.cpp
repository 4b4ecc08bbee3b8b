#include "roomba_rrt/geometry/free_tiles.h"

#include <algorithm>

namespace roomba_rrt::geometry {

FreeTiles::FreeTiles(const OccupancyGrid& grid, bool unknown_is_free)
    : origin_(grid.origin), edge_(kCells * grid.resolution) {
  const int columns = (grid.width + kCells - 1) / kCells,
            rows = (grid.height + kCells - 1) / kCells;
  columns_ = static_cast<std::uint32_t>(std::max(columns, 1));
  for (int tr = 0; tr < rows; ++tr) {
    const int j0 = tr * kCells, j1 = std::min(j0 + kCells, grid.height);
    for (int tc = 0; tc < columns; ++tc) {
      const int i0 = tc * kCells, i1 = std::min(i0 + kCells, grid.width);
      bool any_free = false;
      for (int j = j0; j < j1 && !any_free; ++j) {
        for (int i = i0; i < i1 && !any_free; ++i) {
          any_free = !OccupancyGrid::blockedValue(grid.at(i, j), unknown_is_free);
        }
      }
      if (any_free) tiles_.push_back(static_cast<std::uint32_t>(tr) * columns_ + tc);
    }
  }
}

}  // namespace roomba_rrt::geometry
