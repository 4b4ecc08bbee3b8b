#include "roomba_rrt/geometry/clearance_map.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "roomba_rrt/geometry/distance_transform.h"

namespace roomba_rrt::geometry {
namespace {

// Rounding of a cell's bounds in the walk along a segment: a cell within this of the segment is
// visited too (one more cell to look at, never one less).
constexpr double kWalkSlack = 1e-9;  // m

}  // namespace

ClearanceMap::ClearanceMap(std::shared_ptr<const OccupancyGrid> grid, bool unknown_is_free)
    : grid_(std::move(grid)),
      unknown_is_free_(unknown_is_free),
      distance_(squaredDistanceTransform(*grid_, unknown_is_free)),
      free_tiles_(*grid_, unknown_is_free) {
  // A blocked cell whose four neighbours in the grid are blocked too is inside a wall: its square
  // is never the nearest blocked point to a free point (that lies on the walls' boundary, the
  // square of a blocked cell beside a free one). Mark it −1 so the exact tests skip it. Outside
  // the grid counts as blocked; marked in place, as 0 and −1 both read as blocked (≤ 0).
  const int w = grid_->width, h = grid_->height;
  for (int j = 0; j < h; ++j) {
    std::int32_t* row = &distance_[static_cast<std::size_t>(j) * w];
    const std::int32_t* below = j > 0 ? row - w : nullptr;
    const std::int32_t* above = j + 1 < h ? row + w : nullptr;
    for (int i = 0; i < w; ++i) {
      if (row[i] == 0 && (i == 0 || row[i - 1] <= 0) && (i + 1 == w || row[i + 1] <= 0) &&
          (!below || below[i] <= 0) && (!above || above[i] <= 0)) {
        row[i] = -1;
      }
    }
  }
}

ClearanceMap::Disc ClearanceMap::disc(double radius) const {
  Disc disc;
  disc.radius = radius;
  disc.radius_sq = radius * radius;
  const double k = radius / grid_->resolution;  // the radius in cells
  // The thresholds are moved by a relative 1e-9 towards "look at the squares", so rounding never
  // settles a cell the wrong way; the band only grows by that.
  const double free_at = k + std::sqrt(2.0);
  disc.free_above = free_at * free_at * (1 + 1e-9) + 1e-9;
  const double blocked_at = k - std::sqrt(0.5);
  disc.blocked_below = blocked_at > 0 ? blocked_at * blocked_at * (1 - 1e-9) : 0;
  disc.reach_cells = static_cast<int>(std::ceil(k)) + 1;
  return disc;
}

ClearanceMap::Cell ClearanceMap::classify(int i, int j, const Disc& disc) const {
  const double d = squaredCellDistance(i, j);
  if (d <= 0 || d < disc.blocked_below) return Cell::kBlocked;
  return d > disc.free_above ? Cell::kFree : Cell::kNear;
}

bool ClearanceMap::insideExtent(const Point2& p, double radius) const {
  const Rectangle e = grid_->extent();
  return p.x - radius > e.min_x && p.x + radius < e.max_x && p.y - radius > e.min_y &&
         p.y + radius < e.max_y;
}

template <class Hit>
bool ClearanceMap::anySquare(int i0, int i1, int j0, int j1, Hit hit) const {
  i0 = std::max(i0, 0), j0 = std::max(j0, 0);
  i1 = std::min(i1, grid_->width - 1), j1 = std::min(j1, grid_->height - 1);
  for (int j = j0; j <= j1; ++j) {
    const std::int32_t* row = &distance_[static_cast<std::size_t>(j) * grid_->width];
    for (int i = i0; i <= i1; ++i) {
      if (row[i] == 0 && hit(i, j)) return true;
    }
  }
  return false;
}

bool ClearanceMap::discFree(const Point2& p, const Disc& disc) const {
  if (!insideExtent(p, disc.radius)) return false;
  // Inside the extent, so inside the grid (clamped for a point robot on its last edge).
  const int i = std::min(grid_->column(p.x), grid_->width - 1);
  const int j = std::min(grid_->row(p.y), grid_->height - 1);
  switch (classify(i, j, disc)) {
    case Cell::kFree:
      return true;
    case Cell::kBlocked:
      return false;
    case Cell::kNear:
      break;
  }
  const int reach = disc.reach_cells;
  return !anySquare(i - reach, i + reach, j - reach, j + reach, [&](int si, int sj) {
    return squaredDistance(grid_->square(si, sj), p) <= disc.radius_sq;
  });
}

bool ClearanceMap::clearAroundMidpoint(const Point2& a, const Point2& b, const Disc& disc) const {
  // Every point of the segment is within half its length h of the midpoint m. With d the cells
  // from m's cell's centre to the nearest blocked centre, every blocked square is farther than
  // d − √2 cells from m (m is within √2/2 of its cell's centre, a square's points within √2/2 of
  // its own), so the sweep is free when d − √2 > (h + radius) / resolution. Moved by a relative
  // 1e-9 towards "sweep exactly", as disc(): rounding never certifies a step it should not.
  const Point2 m{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
  // Inside the extent (both ends are), so inside the grid (clamped for rounding on its last edge).
  const int i = std::min(grid_->column(m.x), grid_->width - 1);
  const int j = std::min(grid_->row(m.y), grid_->height - 1);
  const double d_sq = squaredCellDistance(i, j);
  const double need = (0.5 * distance(a, b) + disc.radius) / grid_->resolution + std::sqrt(2.0);
  return d_sq > need * need * (1 + 1e-9) + 1e-9;
}

bool ClearanceMap::sweepFree(const Point2& a, const Point2& b, const Disc& disc) const {
  // The extent is convex: both ends inside it keeps the whole segment inside.
  if (!insideExtent(a, disc.radius) || !insideExtent(b, disc.radius)) return false;
  // Most steps away from walls are settled by one look-up; the rest are swept exactly. (Halving
  // a step into pieces certified one by one was measured slower: near a wall the pieces' exact
  // sweeps each pay the setup and the squares their windows share.)
  return clearAroundMidpoint(a, b, disc) || exactSweepFree(a, b, disc);
}

bool ClearanceMap::exactSweepFree(const Point2& a, const Point2& b, const Disc& disc) const {
  const OccupancyGrid& g = *grid_;
  const Segment segment{a, b};
  const int reach = disc.reach_cells;
  // The window of squares looked at last, so a square is not tested twice for neighbour cells.
  int last_i0 = 1, last_i1 = 0, last_j0 = 1, last_j1 = 0;
  auto nearCell = [&](int i, int j) {
    const int i0 = i - reach, i1 = i + reach, j0 = j - reach, j1 = j + reach;
    const bool hit = anySquare(i0, i1, j0, j1, [&](int si, int sj) {
      const bool seen = si >= last_i0 && si <= last_i1 && sj >= last_j0 && sj <= last_j1;
      return !seen && segmentMeets(segment, g.square(si, sj), disc.radius);
    });
    last_i0 = i0, last_i1 = i1, last_j0 = j0, last_j1 = j1;
    return hit;
  };
  // Walk the cells the segment passes through, column by column: in each column the rows between
  // the segment's heights at the column's two sides.
  const double x_lo = std::min(a.x, b.x), x_hi = std::max(a.x, b.x);
  const int c0 = std::max(g.column(x_lo - kWalkSlack), 0);
  const int c1 = std::min(g.column(x_hi + kWalkSlack), g.width - 1);
  const double slope = a.x == b.x ? 0 : (b.y - a.y) / (b.x - a.x);
  for (int i = c0; i <= c1; ++i) {
    double y_lo, y_hi;
    if (a.x == b.x) {
      y_lo = std::min(a.y, b.y), y_hi = std::max(a.y, b.y);
    } else {
      const double left = std::max(x_lo, g.origin.x + i * g.resolution);
      const double right = std::min(x_hi, g.origin.x + (i + 1) * g.resolution);
      const double y_left = a.y + (left - a.x) * slope, y_right = a.y + (right - a.x) * slope;
      y_lo = std::min(y_left, y_right), y_hi = std::max(y_left, y_right);
    }
    const int r0 = std::max(g.row(y_lo - kWalkSlack), 0);
    const int r1 = std::min(g.row(y_hi + kWalkSlack), g.height - 1);
    for (int j = r0; j <= r1; ++j) {
      switch (classify(i, j, disc)) {
        case Cell::kFree:
          break;
        case Cell::kBlocked:
          return false;
        case Cell::kNear:
          if (nearCell(i, j)) return false;
          break;
      }
    }
  }
  return true;
}

}  // namespace roomba_rrt::geometry
