// A map's free cells as a graph for a disc robot, and a coarse graph of its regions on top, both
// built once per map and radius: what planners/region_astar.h searches.
//
// The fine graph is the inflated grid ROS's grid planners search (navfn, global_planner, Smac
// 2D): a cell centre is a node when the disc is free there (ClearanceMap::discFree, exact against
// every blocked cell's square) and two of the 8 neighbouring centres are joined when the disc
// sweeps freely between them (ClearanceMap::sweepFree). It is kept as one byte of 8 edge bits per
// cell. A cell that lies wholly more than the radius + √2 cells from every blocked centre (the
// distance transform says so in one look-up) is free everywhere, so are both halves of its edges
// to another such cell: only the cells in a band along the inflated walls are swept.
//
// The regions are Sturtevant's sectors (Memory-Efficient Abstractions for Pathfinding, 2007, the
// abstraction of Dragon Age's path planner): the map cut into blocks of B × B cells, each block's
// free cells split into the parts its fine edges join inside it. Two regions of neighbouring
// blocks (8-neighbourhood) are joined when a fine edge crosses from one to the other, so a path
// of the fine graph exists exactly when one of regions does: a doorway one cell wide is a region
// of its own, never lost at the coarse level. Each region has a point, the free centre of its
// cells nearest their mean.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <future>
#include <memory>
#include <mutex>
#include <vector>

#include "roomba_rrt/geometry/clearance_map.h"
#include "roomba_rrt/planning/geometry.h"

namespace roomba_rrt::planning {

/// The largest map (cells) on which region_astar is make_plan's planner: its regions are built
/// in about 30–40 ns a cell (under a second) and hold 1.5 to 4.2 bytes a cell; on larger maps
/// (the 10^8-cell benchmark map: 4 s and 0.4 GB, plans across it of 0.25–0.4 s, where
/// RRT-Connect takes a few ms) make_plan keeps RRT-Connect.
inline constexpr std::size_t kRegionAStarMaxCells = 25'000'000;

class GridRegions {
 public:
  /// The 8 moves of the fine graph (column, row); move k and move k ^ 1 are opposite, moves 0–3
  /// are along the axes.
  static constexpr int kMoves[8][2] = {{1, 0}, {-1, 0},  {0, 1},  {0, -1},
                                       {1, 1}, {-1, -1}, {1, -1}, {-1, 1}};
  /// The block edge used unless asked otherwise (measured on the shared maps: see
  /// doc/planning.md).
  static constexpr int kDefaultBlock = 4;

  /// The fine graph and the regions of `map` for a disc of `radius` (m, ≥ 0), in blocks of
  /// `block` × `block` cells (2, 4, 8 or 16).
  GridRegions(std::shared_ptr<const geometry::ClearanceMap> map, double radius,
              int block = kDefaultBlock);

  const geometry::ClearanceMap& map() const { return *map_; }
  const std::shared_ptr<const geometry::ClearanceMap>& sharedMap() const { return map_; }
  double radius() const { return disc_.radius; }
  const geometry::ClearanceMap::Disc& disc() const { return disc_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int block() const { return block_; }
  /// log2(block()).
  int blockShift() const { return block_shift_; }

  // --- The fine graph.
  /// The cell holding p, or −1 outside the grid.
  int cellOf(const Point2& p) const;
  Point2 centre(int cell) const;
  /// Bit k: the edge from `cell` along kMoves[k] is free (both centres free, the sweep free).
  std::uint8_t edges(int cell) const { return edges_[cell]; }
  /// The disc is free at the cell's centre (a node of the fine graph, maybe without edges).
  bool nodeFree(int cell) const;

  // --- The regions.
  int blocksX() const { return blocks_x_; }
  int blocksY() const { return blocks_y_; }
  int blockOf(int cell) const { return blockAt(cell % width_, cell / width_); }
  int blockAt(int i, int j) const { return (j >> block_shift_) * blocks_x_ + (i >> block_shift_); }
  int regionCount() const { return static_cast<int>(region_block_.size()); }
  /// Where the region stands at the coarse level: the free centre of its cells nearest their
  /// mean.
  const Point2& regionPoint(int region) const { return region_point_[region]; }
  int blockOfRegion(int region) const { return region_block_[region]; }
  /// The regions joined to `region` are adjacency()[k] for k in [adjacencyBegin(region),
  /// adjacencyBegin(region + 1)).
  int adjacencyBegin(int region) const { return adjacency_start_[region]; }
  const std::vector<int>& adjacency() const { return adjacency_; }
  /// The region of a cell whose centre is free and has an edge (−1 otherwise): its block is
  /// labelled again, as when the regions were built.
  int regionOf(int cell) const;
  /// Every cell of the block is free at every point of it (more than radius + √2 cells from every
  /// blocked centre, radius + 1 cells inside the map's edge): open floor, one region.
  bool blockClear(int block) const { return clear_[block] != 0; }
  /// True when every block the segment a-b passes through (each within 1e-9 m of it) is clear:
  /// then the disc sweeps freely along it, proven by a look-up per block, no sweep. False says
  /// nothing (the exact sweep may still find it free).
  bool clearBetween(const Point2& a, const Point2& b) const;
  /// Calls visit(block) for every block the segment a-b passes through (each within 1e-9 m of
  /// it), column by column of blocks, while it returns true; false when it returned false or the
  /// segment leaves the grid.
  template <class Visit>
  bool forEachBlockAlong(const Point2& a, const Point2& b, Visit visit) const;

  /// CPU seconds the constructor took (the fine graph, then the regions).
  double buildSeconds() const { return build_seconds_; }
  /// Bytes held beyond the map: the edge bytes and the regions.
  std::size_t bytes() const;

 private:
  void buildEdges();
  void buildRegions();
  /// Labels the free cells of `block` that have an edge by the part of the block their edges
  /// join them to, 0, 1, ... in the order of their first cell (row by row); 0xff for the others.
  /// `labels` holds block² entries, row by row. Returns the number of parts; `all_joined`, when
  /// given, tells whether every cell of the block has all 8 edges (open floor: one part).
  int labelBlock(int block, std::uint8_t* labels, bool* all_joined = nullptr) const;

  std::shared_ptr<const geometry::ClearanceMap> map_;
  geometry::ClearanceMap::Disc disc_;
  int width_, height_, block_, block_shift_, blocks_x_, blocks_y_;
  std::vector<std::uint8_t> edges_;
  std::vector<std::uint8_t> clear_;      ///< per block: blockClear()
  std::vector<int> block_first_region_;  ///< per block (and one past the last): its first region
  // Per region (the search reads them for every region it reaches: kept, not derived from a
  // cell index, which costs a division each).
  std::vector<Point2> region_point_;
  std::vector<int> region_block_;
  std::vector<int> adjacency_start_, adjacency_;
  double build_seconds_ = 0;
};

/// The GridRegions of one map for each radius asked of it, each built on first use and shared
/// from then on, from any number of threads (a thread asking for regions being built waits for
/// them). A map's planning problem carries one (mapProblem()), so that its regions are built once
/// per map and radius, as a costmap is inflated once: not per plan. The last kKept radii are kept.
class GridRegionsCache {
 public:
  static constexpr std::size_t kKept = 4;

  explicit GridRegionsCache(std::shared_ptr<const geometry::ClearanceMap> map);

  const std::shared_ptr<const geometry::ClearanceMap>& map() const { return map_; }
  /// The regions for a disc of `radius` (m, finite, ≥ 0), built now if they are not yet.
  std::shared_ptr<const GridRegions> get(double radius) const;
  /// The regions for `radius` if they are built already, else nullptr (never waits).
  std::shared_ptr<const GridRegions> ready(double radius) const;

 private:
  struct Entry {
    double radius;
    std::shared_future<std::shared_ptr<const GridRegions>> regions;
  };
  std::shared_ptr<const geometry::ClearanceMap> map_;
  mutable std::mutex mutex_;
  mutable std::vector<Entry> entries_;  ///< the newest last
};

/// Calls visit(column, row) for every square of a grid (origin, square edge `size`, nx × ny
/// squares) that the segment a-b passes through, each within 1e-9 m of it, column by column (the
/// rows between the segment's heights at the column's two sides, as ClearanceMap's exact sweep
/// walks cells), while it returns true; false when it returned false or the segment leaves the
/// grid.
template <class Visit>
bool walkSquares(const Point2& origin, double size, int nx, int ny, const Point2& a,
                 const Point2& b, Visit visit) {
  constexpr double kSlack = 1e-9;  // m
  const auto column = [&](double x) { return static_cast<int>(std::floor((x - origin.x) / size)); };
  const auto row = [&](double y) { return static_cast<int>(std::floor((y - origin.y) / size)); };
  const double x_lo = std::min(a.x, b.x), x_hi = std::max(a.x, b.x);
  const int c0 = column(x_lo - kSlack), c1 = column(x_hi + kSlack);
  if (c0 < 0 || c1 >= nx) return false;
  const double slope = a.x == b.x ? 0 : (b.y - a.y) / (b.x - a.x);
  for (int c = c0; c <= c1; ++c) {
    double y_lo, y_hi;
    if (a.x == b.x) {
      y_lo = std::min(a.y, b.y), y_hi = std::max(a.y, b.y);
    } else {
      const double left = std::max(x_lo, origin.x + c * size);
      const double right = std::min(x_hi, origin.x + (c + 1) * size);
      const double y_left = a.y + (left - a.x) * slope, y_right = a.y + (right - a.x) * slope;
      y_lo = std::min(y_left, y_right), y_hi = std::max(y_left, y_right);
    }
    const int r0 = row(y_lo - kSlack), r1 = row(y_hi + kSlack);
    if (r0 < 0 || r1 >= ny) return false;
    for (int r = r0; r <= r1; ++r) {
      if (!visit(c, r)) return false;
    }
  }
  return true;
}

template <class Visit>
bool GridRegions::forEachBlockAlong(const Point2& a, const Point2& b, Visit visit) const {
  const geometry::OccupancyGrid& g = map_->grid();
  return walkSquares(g.origin, block_ * g.resolution, blocks_x_, blocks_y_, a, b,
                     [&](int c, int r) { return visit(r * blocks_x_ + c); });
}

}  // namespace roomba_rrt::planning
