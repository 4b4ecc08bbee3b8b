// A uniform bucket grid over the bounds, re-sized as it fills: the planner's spatial index.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "roomba_rrt/planning/huge_page_allocator.h"
#include "roomba_rrt/planning/nearest_neighbors.h"

namespace roomba_rrt::planning {

/// Cells (about square, however elongated the bounds) covering the bounds; each cell stores the
/// coordinates of its first three points inline (one 64-byte cache line), further points in a
/// shared overflow list. When the points outnumber 1.5 per cell the grid doubles its cell count and
/// re-inserts everything, so a query looks at about nine cells whatever the tree size. A query
/// visits rings of cells around the query's cell until no unvisited cell can hold a closer point.
/// Why not a kd-tree: at 10^6 nodes the cost is cache misses, and this layout touches three
/// short contiguous runs of memory per query (see doc/planning.md for the measurements).
class GridNearestNeighbors final : public NearestNeighbors {
 public:
  void clear(const Bounds& bounds) override;
  void add(const Point2& p, int index) override;
  Neighbor nearestNeighbor(const Point2& q) const override;
  void withinRadius(const Point2& q, double radius, std::vector<int>& out) const override;
  int size() const override { return size_; }
  int cellCount() const { return static_cast<int>(cells_.size()); }

 private:
#pragma pack(push, 4)
  struct Entry {  // 20 bytes: three fit in a cache line with the overflow link
    double x = 0, y = 0;
    std::int32_t index = -1;  ///< -1: empty slot
  };
#pragma pack(pop)
  static constexpr int kInline = 3;
  struct alignas(64) Cell {
    Entry inline_entries[kInline];  ///< filled from the front
    std::int32_t overflow = -1;     ///< head of this cell's chain in overflow_, -1 if none
  };
  static_assert(sizeof(Cell) == 64, "a cell is one cache line");
  struct OverflowEntry {
    Entry entry;
    std::int32_t next;
  };

  void resize(int target_cells);
  void insert(const Entry& e);
  int cellX(double x) const {
    const double i = std::floor((x - bounds_.x_min) * inv_cell_w_);
    return i <= 0 ? 0 : (i >= nx_ - 1 ? nx_ - 1 : static_cast<int>(i));
  }
  int cellY(double y) const {
    const double i = std::floor((y - bounds_.y_min) * inv_cell_h_);
    return i <= 0 ? 0 : (i >= ny_ - 1 ? ny_ - 1 : static_cast<int>(i));
  }
  const Cell& cell(int cx, int cy) const { return cells_[static_cast<std::size_t>(cy) * nx_ + cx]; }
  template <typename Visit>
  void forEachInCell(const Cell& cell, Visit&& visit) const {
    for (int i = 0; i < kInline && cell.inline_entries[i].index >= 0; ++i) {
      visit(cell.inline_entries[i]);
    }
    for (std::int32_t o = cell.overflow; o >= 0; o = overflow_[o].next) visit(overflow_[o].entry);
  }

  Bounds bounds_;
  double cell_w_ = 1, cell_h_ = 1, inv_cell_w_ = 1, inv_cell_h_ = 1;
  int nx_ = 1, ny_ = 1;
  int size_ = 0;
  std::vector<Cell, HugePageAllocator<Cell>> cells_;
  std::vector<OverflowEntry> overflow_;
};

}  // namespace roomba_rrt::planning
