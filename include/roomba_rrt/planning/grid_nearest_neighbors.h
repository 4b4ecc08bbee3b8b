// A uniform bucket grid over the bounds, re-sized as it fills: the planner's spatial index.
#pragma once

#include <cstdint>
#include <vector>

#include "roomba_rrt/planning/nearest_neighbors.h"

namespace roomba_rrt::planning {

/// Square cells covering the bounds; each cell stores the coordinates of its first two points
/// inline (one 64-byte cache line), further points in a shared overflow list. When the points
/// outnumber 1.5 per cell the grid doubles its cell count and re-inserts everything, so a query
/// looks at about nine cells whatever the tree size. A query visits rings of cells around the
/// query's cell until no unvisited cell can hold a closer point.
/// Why not a kd-tree: at 10^6 nodes the cost is cache misses, and this layout touches three
/// short contiguous runs of memory per query (see doc/planning.md for the measurements).
class GridNearestNeighbors final : public NearestNeighbors {
 public:
  void clear(const Bounds& bounds) override;
  void add(const Point2& p, int index) override;
  int nearest(const Point2& q) const override;
  void withinRadius(const Point2& q, double radius, std::vector<int>& out) const override;
  int size() const override { return size_; }
  int cellCount() const { return static_cast<int>(cells_.size()); }

 private:
  struct Entry {
    double x, y;
    std::int32_t index;
  };
  struct alignas(64) Cell {
    std::int32_t count = 0;      ///< points in this cell (inline and overflow)
    std::int32_t overflow = -1;  ///< head of this cell's chain in overflow_, -1 if none
    Entry inline_entries[2];
  };
  struct OverflowEntry {
    Entry entry;
    std::int32_t next;
  };
  static constexpr int kInline = 2;

  void resize(int target_cells);
  void insert(const Entry& e);
  int cellX(double x) const;
  int cellY(double y) const;
  template <typename Visit>
  void forEachInCell(int cx, int cy, Visit&& visit) const;

  Bounds bounds_;
  double cell_size_ = 1, inv_cell_size_ = 1;
  int nx_ = 1, ny_ = 1;
  int size_ = 0;
  std::vector<Cell> cells_;
  std::vector<OverflowEntry> overflow_;
};

}  // namespace roomba_rrt::planning
