// Where on a map a robot can be at all: the tiles of a few cells that hold a free cell. Drawing a
// point from them instead of the map's rectangle wastes no draws on unknown border and walls (on
// turtlebot3_world the floor is 4 % of the rectangle).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "roomba_rrt/geometry/geometry.h"
#include "roomba_rrt/geometry/occupancy_grid.h"

namespace roomba_rrt::geometry {

/// The map cut into square tiles of kCells × kCells cells; the list of those with at least one
/// cell a robot is not blocked on (OccupancyGrid::blocked()). A point drawn uniformly in a tile
/// drawn uniformly from the list is uniform over the listed tiles' area, which holds every free
/// point of the map, so rejecting the points that are not free leaves a uniform free point.
class FreeTiles {
 public:
  static constexpr int kCells = 8;  ///< tile edge in cells: 4 bytes per 64 cells at most

  FreeTiles(const OccupancyGrid& grid, bool unknown_is_free);

  std::size_t size() const { return tiles_.size(); }
  bool empty() const { return tiles_.empty(); }
  /// The area of the listed tiles, m² (the sampler compares it with its bounds').
  double area() const { return static_cast<double>(tiles_.size()) * edge_ * edge_; }
  /// The point at fractions (u, v) ∈ [0, 1)² of the tile at fraction t ∈ [0, 1) of the list.
  /// May lie beyond the grid's last row or column (a tile at the edge overhangs it).
  Point2 point(double t, double u, double v) const {
    const std::size_t k = std::min(static_cast<std::size_t>(t * tiles_.size()), tiles_.size() - 1);
    const std::uint32_t column = tiles_[k] % columns_, row = tiles_[k] / columns_;
    return {origin_.x + (column + u) * edge_, origin_.y + (row + v) * edge_};
  }

 private:
  Point2 origin_;
  double edge_ = 0;                   ///< m
  std::uint32_t columns_ = 1;         ///< tiles per row
  std::vector<std::uint32_t> tiles_;  ///< row · columns_ + column of each listed tile
};

}  // namespace roomba_rrt::geometry
