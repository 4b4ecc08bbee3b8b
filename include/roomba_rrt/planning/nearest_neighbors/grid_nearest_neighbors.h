// A uniform bucket grid over the bounds, re-sized as it fills: the planner's spatial index.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "roomba_rrt/planning/nearest_neighbors/huge_page_allocator.h"
#include "roomba_rrt/planning/nearest_neighbors/nearest_neighbors.h"

namespace roomba_rrt::planning {

/// Cells (about square, however elongated the bounds) covering the bounds; each cell stores its
/// first five points inline (one 64-byte cache line), further points in a shared overflow list.
/// When the points outnumber 4 per cell the grid doubles its cell count and re-inserts
/// everything, so a query looks at about nine cells whatever the tree size. A query visits rings
/// of cells around the query's cell until no unvisited cell can hold a closer point.
/// Memory: a cell keeps each point as float coordinates and the node index (12 bytes), about
/// 19 bytes per point with the empty slots (a 10^6-node tree: 16 MB). Floats only pre-select:
/// a float coordinate is within about 2^-24 |x| of the exact one, so the search keeps every point
/// whose float distance is within that error of the best, and decides among those (nearly always
/// one) by the exact coordinates, read from the caller's array (clear()'s `positions`). The
/// answer is therefore exactly brute force's.
/// A query far from every point (a region the tree has not reached, e.g. beyond scenario d's
/// wall) would cross many empty rings: after three rings it continues over blocks of 8 x 8 cells,
/// skipping empty blocks by their point count.
/// While it holds at most 512 points it has no grid and scans them linearly: on trees that
/// small one contiguous scan is faster than any index. The scan reads the coordinates as two
/// separate arrays (x's, y's), four points per SIMD instruction (see linearNearest() in the .cpp).
/// Why not a kd-tree: at 10^6 nodes the cost is cache misses, and this layout touches three
/// short contiguous runs of memory per query (see doc/performance.md for the
/// measurements).
class GridNearestNeighbors final : public NearestNeighbors {
 public:
  /// Up to this many points a linear scan of one contiguous array beats any grid (the lab's trees
  /// have a few hundred nodes); the grid is built when the next point arrives.
  static constexpr int kLinearScanLimit = 512;

  void clear(const Bounds& bounds, const std::vector<Point2>& positions) override;
  // add() and nearestNeighbor() handle the lab's case (a small tree, added in index order) inline:
  // a planner that calls them through this class, not the interface, runs that case without a
  // function call (see solveRrt()).
  void add(const Point2& p, int index) override {
    ++size_;
    if (cells_.empty() && size_ <= kLinearScanLimit) {
      addLinear(p, index);
    } else {
      addToGrid(p, index);
    }
  }
  Neighbor nearestNeighbor(const Point2& q) const override {
    if (cells_.empty() && linear_ids_increasing_ && size_ > 0) {
      const int slot = linearNearest(linear_x_.data(), linear_y_.data(), size_, q.x, q.y);
      if (slot >= 0) return linearNeighbor(slot);
    }
    return searchNearest(q);
  }
  void withinRadius(const Point2& q, double radius, std::vector<int>& out) const override;
  int size() const override { return size_; }
  int cellCount() const { return static_cast<int>(cells_.size()); }

 private:
  struct Entry {              // 12 bytes: five fit in a cache line with the overflow link
    float x = 0, y = 0;       ///< the coordinates rounded to float (a pre-filter only)
    std::int32_t index = -1;  ///< -1: empty slot
  };
  static constexpr int kInline = 5;
  struct alignas(64) Cell {
    Entry inline_entries[kInline];  ///< filled from the front
    std::int32_t overflow = -1;     ///< head of this cell's chain in overflow_, -1 if none
  };
  static_assert(sizeof(Cell) == 64, "a cell is one cache line");
  struct OverflowEntry {
    Entry entry;
    std::int32_t next;
  };

  static constexpr int kBlock = 8;  ///< cells per block side (the coarse level)

  /// True when nothing outside the (2r+1)^2 units around unit (ux, uy) can be closer than
  /// sqrt(best_d2), or when those units cover the whole grid. Units are cells or blocks.
  bool ringSearchDone(const Point2& q, int ux, int uy, int r, int units_x, int units_y,
                      double unit_w, double unit_h, double best_d2) const;
  /// Squared distance from q to the nearest point of cell (cx, cy), rounded down: no point stored
  /// in that cell is closer.
  double cellGapD2(const Point2& q, int cx, int cy) const;
  /// The same for the cells [cx0, cx1] x [cy0, cy1].
  double rangeGapD2(const Point2& q, int cx0, int cx1, int cy0, int cy1) const;
  /// Calls visit(x, y) for the units (cells or blocks) at Chebyshev distance r from (ux, uy).
  template <typename Visit>
  static void forEachOnRing(int ux, int uy, int r, int units_x, int units_y, Visit&& visit) {
    const int x0 = std::max(0, ux - r), x1 = std::min(units_x - 1, ux + r);
    const int y0 = std::max(0, uy - r), y1 = std::min(units_y - 1, uy + r);
    for (int y = y0; y <= y1; ++y) {
      if (y == uy - r || y == uy + r) {
        for (int x = x0; x <= x1; ++x) visit(x, y);
      } else {
        if (ux - r >= 0) visit(ux - r, y);
        if (r > 0 && ux + r < units_x) visit(ux + r, y);
      }
    }
  }
  std::size_t blockOf(int cx, int cy) const {
    return static_cast<std::size_t>(cy / kBlock) * bx_ + cx / kBlock;
  }
  void resize(int target_cells);
  void insert(const Entry& e);
  /// The candidates of a grid query: see nearestNeighbor() in the .cpp.
  struct Search;
  Neighbor exactNearest(const Point2& q, const Search& search) const;
  // A NaN position (0 * inf in degenerate bounds, which validate() refuses) goes to cell 0 and
  // +-inf to an end: only a number strictly between 0 and the last cell is converted to int.
  int cellX(double x) const {
    const double i = std::floor((x - bounds_.x_min) * inv_cell_w_);
    return !(i > 0) ? 0 : (i >= nx_ - 1 ? nx_ - 1 : static_cast<int>(i));
  }
  int cellY(double y) const {
    const double i = std::floor((y - bounds_.y_min) * inv_cell_h_);
    return !(i > 0) ? 0 : (i >= ny_ - 1 ? ny_ - 1 : static_cast<int>(i));
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
  const std::vector<Point2>* positions_ = nullptr;  ///< exact coordinates, by node index
  /// Largest |x| or |y| added so far: a float coordinate is within 2^-24 of it of the exact one.
  double max_abs_coordinate_ = 0;
  double cell_w_ = 1, cell_h_ = 1, inv_cell_w_ = 1, inv_cell_h_ = 1;
  int nx_ = 1, ny_ = 1;
  int size_ = 0;
  std::vector<Cell, HugePageAllocator<Cell>> cells_;
  std::vector<OverflowEntry> overflow_;
  /// All points while there are few (no grid yet), as separate arrays so that a scan loads four
  /// x's (or y's) at once. The arrays are padded with NaN up to a multiple of kLinearPad, which
  /// never compares less than a distance; ids_ has no padding.
  static constexpr int kLinearPad = 8;
  std::vector<double> linear_x_, linear_y_;
  std::vector<std::int32_t> linear_ids_;
  /// True while linear_ids_ only grows (a planner adds nodes in index order): then the first
  /// minimum in scan order is also the one with the lowest index.
  bool linear_ids_increasing_ = true;
  void addLinear(const Point2& p, int index) {
    const std::size_t slot = linear_ids_.size();
    if (slot == linear_x_.size()) openLinearSlots();
    linear_x_[slot] = p.x;
    linear_y_[slot] = p.y;
    if (slot > 0 && index <= linear_ids_.back()) linear_ids_increasing_ = false;
    linear_ids_.push_back(index);
  }
  /// Appends 64 NaN slots (a multiple of kLinearPad) to linear_x_ and linear_y_.
  void openLinearSlots();
  /// The slot of the nearest of the `n` linear points to (qx, qy), the first in slot order among
  /// equals; -1 when every distance overflows. See the .cpp.
  static int linearNearest(const double* xs, const double* ys, int n, double qx, double qy);
  /// add() once the linear phase is over: builds or grows the grid, inserts p.
  void addToGrid(const Point2& p, int index);
  /// nearestNeighbor() of any state (grid, or points out of index order, or overflow).
  Neighbor searchNearest(const Point2& q) const;
  Neighbor linearNeighbor(int slot) const {
    return {linear_ids_[slot], {linear_x_[slot], linear_y_[slot]}};
  }
  int bx_ = 1, by_ = 1;                    ///< blocks along x and y
  std::vector<std::int32_t> block_count_;  ///< points per block
};

}  // namespace roomba_rrt::planning
