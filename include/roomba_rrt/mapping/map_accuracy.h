// How well a built map agrees with the true world: what the mapper's tests and the accuracy
// benchmark measure. Each cell's square is classed against the world's exact shapes (walls,
// furniture, map cells): free (meets no obstacle), occupied (inside one) or mixed (an obstacle's
// edge crosses it: either answer agrees, the grid cannot say better). ROS-free.
#pragma once

#include <cstddef>

#include "roomba_rrt/geometry/occupancy_grid.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::mapping {

enum class CellTruth { kFree, kMixed, kOccupied };

/// The truth of the closed square `square` in `world`: kOccupied when an obstacle (the outside
/// of the room, a piece of furniture, the blocked and unknown cells of the world's map) covers
/// it, kFree when no obstacle meets its interior, kMixed otherwise.
CellTruth cellTruth(const world::World& world, const geometry::Rectangle& square);

struct MapAccuracy {
  std::size_t known = 0;       ///< cells the map knows (free or occupied)
  std::size_t agreeing = 0;    ///< of those, free where the truth is not occupied, or occupied
                               ///< where it is not free
  std::size_t occupied = 0;    ///< cells the map holds occupied
  std::size_t walls_off = 0;   ///< occupied cells with no obstacle within one cell
  std::size_t free_known = 0;  ///< free cells
  double agreement() const {
    return known ? static_cast<double>(agreeing) / static_cast<double>(known) : 1.0;
  }
};

/// Compares every known cell of `map` with the world.
MapAccuracy compare(const geometry::OccupancyGrid& map, const world::World& world);

}  // namespace roomba_rrt::mapping
