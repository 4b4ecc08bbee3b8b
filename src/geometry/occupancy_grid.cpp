#include "roomba_rrt/geometry/occupancy_grid.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace roomba_rrt::geometry {
namespace {

/// Calls visit(i, j) for every cell whose square may come within `reach` of p (the cells of the
/// bounding box of the disc, one ring more for rounding), outside the grid included, until
/// visit returns true; returns whether one did.
template <class Visit>
bool anyCellNear(const OccupancyGrid& grid, const Point2& p, double reach, Visit visit) {
  const int i0 = grid.column(p.x - reach) - 1, i1 = grid.column(p.x + reach) + 1;
  const int j0 = grid.row(p.y - reach) - 1, j1 = grid.row(p.y + reach) + 1;
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      if (visit(i, j)) return true;
    }
  }
  return false;
}

/// The t-interval of a + t (b − a), t ∈ [0, 1], whose x lies in [lo, hi]; empty when lo > hi.
std::pair<double, double> clipToBand(double ax, double bx, double lo, double hi) {
  const double dx = bx - ax;
  if (dx == 0) return (ax >= lo && ax <= hi) ? std::pair{0.0, 1.0} : std::pair{1.0, 0.0};
  double t0 = (lo - ax) / dx, t1 = (hi - ax) / dx;
  if (t0 > t1) std::swap(t0, t1);
  return {std::max(t0, 0.0), std::min(t1, 1.0)};
}

}  // namespace

Rectangle OccupancyGrid::knownExtent() const {
  int min_i = width, max_i = -1, min_j = height, max_j = -1;
  for (int j = 0; j < height; ++j) {
    const std::int8_t* row = cells.data() + static_cast<std::size_t>(j) * width;
    int first = 0;
    while (first < width && row[first] == kUnknown) ++first;
    if (first == width) continue;
    int last = width - 1;
    while (row[last] == kUnknown) --last;
    min_i = std::min(min_i, first);
    max_i = std::max(max_i, last);
    min_j = std::min(min_j, j);
    max_j = j;
  }
  if (max_j < 0) return extent();
  return {origin.x + min_i * resolution, origin.y + min_j * resolution,
          origin.x + (max_i + 1) * resolution, origin.y + (max_j + 1) * resolution};
}

double distanceToBlocked(const OccupancyGrid& grid, const Point2& p, double reach,
                         bool unknown_is_free) {
  double best_sq = reach * reach;
  anyCellNear(grid, p, reach, [&](int i, int j) {
    if (grid.blocked(i, j, unknown_is_free)) {
      best_sq = std::min(best_sq, squaredDistance(grid.square(i, j), p));
    }
    return false;
  });
  return std::sqrt(best_sq);
}

bool blockedWithin(const OccupancyGrid& grid, const Point2& p, double reach, bool unknown_is_free) {
  // The cells distanceToBlocked visits: sqrt(the least squared distance) < reach holds exactly
  // when it holds for one of them (sqrt never decreases).
  return anyCellNear(grid, p, reach, [&](int i, int j) {
    return grid.blocked(i, j, unknown_is_free) &&
           std::sqrt(squaredDistance(grid.square(i, j), p)) < reach;
  });
}

bool segmentMeetsBlocked(const OccupancyGrid& grid, const Segment& segment, double margin,
                         bool unknown_is_free) {
  const Point2 &a = segment.a, &b = segment.b;
  const int i0 = grid.column(std::min(a.x, b.x) - margin) - 1;
  const int i1 = grid.column(std::max(a.x, b.x) + margin) + 1;
  for (int i = i0; i <= i1; ++i) {
    // The part of the segment over column i's band grown by the margin, and its rows.
    const double left = grid.origin.x + i * grid.resolution;
    const auto [t0, t1] = clipToBand(a.x, b.x, left - margin, left + grid.resolution + margin);
    if (t0 > t1) continue;
    const double ya = a.y + t0 * (b.y - a.y), yb = a.y + t1 * (b.y - a.y);
    const int j0 = grid.row(std::min(ya, yb) - margin) - 1;
    const int j1 = grid.row(std::max(ya, yb) + margin) + 1;
    for (int j = j0; j <= j1; ++j) {
      if (grid.blocked(i, j, unknown_is_free) && segmentMeets(segment, grid.square(i, j), margin)) {
        return true;
      }
    }
  }
  return false;
}

bool discMeetsBlocked(const OccupancyGrid& grid, const Point2& p, double radius,
                      bool unknown_is_free) {
  return anyCellNear(grid, p, radius, [&](int i, int j) {
    return grid.blocked(i, j, unknown_is_free) && withinMargin(grid.square(i, j), p, radius);
  });
}

void blockedSquaresNear(const OccupancyGrid& grid, const Point2& p, double radius,
                        std::vector<Rectangle>& out, bool unknown_is_free) {
  out.clear();
  anyCellNear(grid, p, radius, [&](int i, int j) {
    if (grid.blocked(i, j, unknown_is_free) && withinMargin(grid.square(i, j), p, radius)) {
      out.push_back(grid.square(i, j));
    }
    return false;
  });
}

}  // namespace roomba_rrt::geometry
