#include "roomba_rrt/geometry/occupancy_grid.h"

#include <algorithm>
#include <cmath>

namespace roomba_rrt::geometry {
namespace {

/// Calls visit(i, j) for every cell whose square may come within `reach` of p (the cells of the
/// bounding box of the disc, one ring more for rounding), outside the grid included.
template <class Visit>
void forCellsNear(const OccupancyGrid& grid, const Point2& p, double reach, Visit visit) {
  const int i0 = grid.column(p.x - reach) - 1, i1 = grid.column(p.x + reach) + 1;
  const int j0 = grid.row(p.y - reach) - 1, j1 = grid.row(p.y + reach) + 1;
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) visit(i, j);
  }
}

}  // namespace

double distanceToBlocked(const OccupancyGrid& grid, const Point2& p, double reach,
                         bool unknown_is_free) {
  double best_sq = reach * reach;
  forCellsNear(grid, p, reach, [&](int i, int j) {
    if (grid.blocked(i, j, unknown_is_free)) {
      best_sq = std::min(best_sq, squaredDistance(grid.square(i, j), p));
    }
  });
  return std::sqrt(best_sq);
}

double segmentDistanceToBlocked(const OccupancyGrid& grid, const Segment& segment, double reach,
                                bool unknown_is_free) {
  const Point2 &a = segment.a, &b = segment.b;
  const int i0 = grid.column(std::min(a.x, b.x) - reach) - 1;
  const int i1 = grid.column(std::max(a.x, b.x) + reach) + 1;
  const int j0 = grid.row(std::min(a.y, b.y) - reach) - 1;
  const int j1 = grid.row(std::max(a.y, b.y) + reach) + 1;
  double best = reach;
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      if (grid.blocked(i, j, unknown_is_free)) {
        best = std::min(best, distance(grid.square(i, j), segment));
      }
    }
  }
  return best;
}

bool discMeetsBlocked(const OccupancyGrid& grid, const Point2& p, double radius,
                      bool unknown_is_free) {
  bool meets = false;
  forCellsNear(grid, p, radius, [&](int i, int j) {
    if (!meets && grid.blocked(i, j, unknown_is_free) &&
        withinMargin(grid.square(i, j), p, radius)) {
      meets = true;
    }
  });
  return meets;
}

void blockedSquaresNear(const OccupancyGrid& grid, const Point2& p, double radius,
                        std::vector<Rectangle>& out, bool unknown_is_free) {
  out.clear();
  forCellsNear(grid, p, radius, [&](int i, int j) {
    if (grid.blocked(i, j, unknown_is_free) && withinMargin(grid.square(i, j), p, radius)) {
      out.push_back(grid.square(i, j));
    }
  });
}

}  // namespace roomba_rrt::geometry
