#include "roomba_rrt/planning/grid_nearest_neighbors.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roomba_rrt::planning {
namespace {

constexpr int kInitialCells = 64;
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
  resize(kInitialCells);
}

void GridNearestNeighbors::resize(int target_cells) {
  // Take every entry out, lay a finer grid, put them back.
  std::vector<Entry> entries;
  entries.reserve(size_);
  for (const Cell& c : cells_) forEachInCell(c, [&](const Entry& e) { entries.push_back(e); });
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
  for (const Entry& e : entries) insert(e);
}

void GridNearestNeighbors::insert(const Entry& e) {
  Cell& cell = cells_[static_cast<std::size_t>(cellY(e.y)) * nx_ + cellX(e.x)];
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
  if (size_ + 1 > kMaxPointsPerCell * cellCount()) resize(2 * cellCount());
  insert({p.x, p.y, index});
  ++size_;
}

Neighbor GridNearestNeighbors::nearestNeighbor(const Point2& q) const {
  if (size_ == 0) return {};
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
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (int r = 0;; ++r) {
    // Visit the ring of cells at Chebyshev distance r around (cx, cy).
    const int x0 = std::max(0, cx - r), x1 = std::min(nx_ - 1, cx + r);
    const int y0 = std::max(0, cy - r), y1 = std::min(ny_ - 1, cy + r);
    for (int y = y0; y <= y1; ++y) {
      if (y == cy - r || y == cy + r) {
        for (int x = x0; x <= x1; ++x) forEachInCell(cell(x, y), consider);
      } else {
        if (cx - r >= 0) forEachInCell(cell(cx - r, y), consider);
        if (r > 0 && cx + r < nx_) forEachInCell(cell(cx + r, y), consider);
      }
    }
    // Done when the visited block covers the grid, or nothing outside it can be closer.
    const bool left = cx - r > 0, right = cx + r < nx_ - 1;
    const bool down = cy - r > 0, up = cy + r < ny_ - 1;
    if (!left && !right && !down && !up) break;
    double gap = kInf;
    if (left) gap = std::min(gap, q.x - (bounds_.x_min + (cx - r) * cell_w_));
    if (right) gap = std::min(gap, bounds_.x_min + (cx + r + 1) * cell_w_ - q.x);
    if (down) gap = std::min(gap, q.y - (bounds_.y_min + (cy - r) * cell_h_));
    if (up) gap = std::min(gap, bounds_.y_min + (cy + r + 1) * cell_h_ - q.y);
    gap -= kBorderSlack;
    if (gap > 0 && best_d2 < gap * gap) break;
  }
  return {best->index, {best->x, best->y}};
}

void GridNearestNeighbors::withinRadius(const Point2& q, double radius,
                                        std::vector<int>& out) const {
  out.clear();
  const double r2 = radius * radius;
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
