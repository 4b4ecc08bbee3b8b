#include "roomba_rrt/planning/grid_nearest_neighbors.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roomba_rrt::planning {
namespace {

// Up to this many points a linear scan of one contiguous array beats any grid (the lab's trees
// have a few hundred nodes); the grid is built when the next point arrives.
constexpr int kLinearScanLimit = 512;
constexpr int kFirstGridCells = 512;
constexpr double kMaxPointsPerCell = 1.5;  // grow (double the cells) beyond this load
// Cell borders are computed in floating point; shrinking the "nothing closer outside" distance
// by this much keeps the answer exact (identical to brute force) despite rounding.
constexpr double kBorderSlack = 1e-9;

}  // namespace

void GridNearestNeighbors::clear(const Bounds& bounds) {
  bounds_ = bounds;
  size_ = 0;
  cells_.clear();
  overflow_.clear();
  linear_.clear();
}

void GridNearestNeighbors::resize(int target_cells) {
  // Take every entry out, lay a finer grid, put them back.
  std::vector<Entry> entries;
  entries.reserve(size_);
  for (const Cell& c : cells_) forEachInCell(c, [&](const Entry& e) { entries.push_back(e); });
  entries.insert(entries.end(), linear_.begin(), linear_.end());
  linear_.clear();
  // About square cells, but never more cells along one axis than in total (thin bounds).
  const double width = bounds_.x_max - bounds_.x_min;
  const double height = bounds_.y_max - bounds_.y_min;
  const double columns = std::round(std::sqrt(target_cells * width / height));
  nx_ = static_cast<int>(std::clamp(columns, 1.0, static_cast<double>(target_cells)));
  ny_ = std::max(1, target_cells / nx_);
  cell_w_ = width / nx_;
  cell_h_ = height / ny_;
  inv_cell_w_ = nx_ / width;
  inv_cell_h_ = ny_ / height;
  cells_.assign(static_cast<std::size_t>(nx_) * ny_, Cell{});
  overflow_.clear();
  bx_ = (nx_ + kBlock - 1) / kBlock;
  by_ = (ny_ + kBlock - 1) / kBlock;
  block_count_.assign(static_cast<std::size_t>(bx_) * by_, 0);
  for (const Entry& e : entries) insert(e);
}

void GridNearestNeighbors::insert(const Entry& e) {
  const int cx = cellX(e.x), cy = cellY(e.y);
  ++block_count_[blockOf(cx, cy)];
  Cell& cell = cells_[static_cast<std::size_t>(cy) * nx_ + cx];
  for (Entry& slot : cell.inline_entries) {
    if (slot.index < 0) {
      slot = e;
      return;
    }
  }
  overflow_.push_back({e, cell.overflow});
  cell.overflow = static_cast<std::int32_t>(overflow_.size() - 1);
}

void GridNearestNeighbors::add(const Point2& p, int index) {
  ++size_;
  if (cells_.empty() && size_ <= kLinearScanLimit) {
    linear_.push_back({p.x, p.y, index});
    return;
  }
  if (cells_.empty()) {
    resize(kFirstGridCells);
  } else if (size_ > kMaxPointsPerCell * cellCount()) {
    resize(2 * cellCount());
  }
  insert({p.x, p.y, index});
}

Neighbor GridNearestNeighbors::nearestNeighbor(const Point2& q) const {
  if (size_ == 0) return {};
  if (cells_.empty()) {
    const Entry* best = &linear_[0];
    double best_d2 = std::numeric_limits<double>::infinity();
    for (const Entry& e : linear_) {
      const double dx = e.x - q.x;
      const double dy = e.y - q.y;
      const double d2 = dx * dx + dy * dy;
      if (d2 < best_d2 || (d2 == best_d2 && e.index < best->index)) {
        best_d2 = d2;
        best = &e;
      }
    }
    return {best->index, {best->x, best->y}};
  }
  const int cx = cellX(q.x);
  const int cy = cellY(q.y);
  // At 10^6 points every cell is a cache miss: ask for the 3 x 3 block at once, so the
  // misses overlap instead of queueing (each row of the block is contiguous).
  for (int y = std::max(0, cy - 1); y <= std::min(ny_ - 1, cy + 1); ++y) {
    const Cell* row = &cell(std::max(0, cx - 1), y);
    for (int x = std::max(0, cx - 1); x <= std::min(nx_ - 1, cx + 1); ++x, ++row) {
      __builtin_prefetch(row);
    }
  }
  const Entry* best = nullptr;
  double best_d2 = std::numeric_limits<double>::infinity();
  auto consider = [&](const Entry& e) {
    const double dx = e.x - q.x;
    const double dy = e.y - q.y;
    const double d2 = dx * dx + dy * dy;  // the same formula as squaredDistance()
    if (d2 < best_d2 || (d2 == best_d2 && e.index < best->index)) {
      best_d2 = d2;
      best = &e;
    }
  };
  // 1. Rings of cells around the query's cell; enough whenever the tree is near.
  constexpr int kCellRings = 3;
  for (int r = 0; r < kCellRings; ++r) {
    forEachOnRing(cx, cy, r, nx_, ny_, [&](int x, int y) { forEachInCell(cell(x, y), consider); });
    if (ringSearchDone(q, cx, cy, r, nx_, ny_, cell_w_, cell_h_, best_d2)) {
      return {best->index, {best->x, best->y}};
    }
  }
  // 2. Far from every point: rings of blocks, visiting only blocks that hold points. (Cells of
  //    step 1 may be visited again; the minimum stays the same.)
  auto visitBlock = [&](int x, int y) {
    if (block_count_[static_cast<std::size_t>(y) * bx_ + x] == 0) return;
    for (int fy = y * kBlock; fy < std::min(ny_, (y + 1) * kBlock); ++fy) {
      for (int fx = x * kBlock; fx < std::min(nx_, (x + 1) * kBlock); ++fx) {
        forEachInCell(cell(fx, fy), consider);
      }
    }
  };
  const int bx = cx / kBlock, by = cy / kBlock;
  for (int r = 0;; ++r) {
    forEachOnRing(bx, by, r, bx_, by_, visitBlock);
    if (ringSearchDone(q, bx, by, r, bx_, by_, kBlock * cell_w_, kBlock * cell_h_, best_d2)) {
      break;
    }
  }
  return {best->index, {best->x, best->y}};
}

bool GridNearestNeighbors::ringSearchDone(const Point2& q, int ux, int uy, int r, int units_x,
                                          int units_y, double unit_w, double unit_h,
                                          double best_d2) const {
  const bool left = ux - r > 0, right = ux + r < units_x - 1;
  const bool down = uy - r > 0, up = uy + r < units_y - 1;
  if (!left && !right && !down && !up) return true;  // the whole grid has been visited
  double gap = std::numeric_limits<double>::infinity();
  if (left) gap = std::min(gap, q.x - (bounds_.x_min + (ux - r) * unit_w));
  if (right) gap = std::min(gap, bounds_.x_min + (ux + r + 1) * unit_w - q.x);
  if (down) gap = std::min(gap, q.y - (bounds_.y_min + (uy - r) * unit_h));
  if (up) gap = std::min(gap, bounds_.y_min + (uy + r + 1) * unit_h - q.y);
  gap -= kBorderSlack;
  return gap > 0 && best_d2 < gap * gap;
}

void GridNearestNeighbors::withinRadius(const Point2& q, double radius,
                                        std::vector<int>& out) const {
  out.clear();
  const double r2 = radius * radius;
  for (const Entry& e : linear_) {
    const double dx = e.x - q.x;
    const double dy = e.y - q.y;
    if (dx * dx + dy * dy <= r2) out.push_back(e.index);
  }
  if (cells_.empty()) return;
  for (int y = cellY(q.y - radius); y <= cellY(q.y + radius); ++y) {
    for (int x = cellX(q.x - radius); x <= cellX(q.x + radius); ++x) {
      forEachInCell(cell(x, y), [&](const Entry& e) {
        const double dx = e.x - q.x;
        const double dy = e.y - q.y;
        if (dx * dx + dy * dy <= r2) out.push_back(e.index);
      });
    }
  }
}

}  // namespace roomba_rrt::planning
