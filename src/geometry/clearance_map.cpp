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

bool ClearanceMap::sweepFree(const Point2& a, const Point2& b, const Disc& disc) const {
  // The extent is convex: both ends inside it keeps the whole segment inside.
  if (!insideExtent(a, disc.radius) || !insideExtent(b, disc.radius)) return false;
  // Most steps away from walls are settled by one look-up; the rest are swept exactly. (Halving
  // a step into pieces certified one by one was measured slower: near a wall the pieces' exact
  // sweeps each pay the setup and the squares their windows share.)
  return clearAroundMidpoint(a, b, disc) || exactSweepFree(a, b, disc);
}

template <class Visit>
bool ClearanceMap::forEachCellOnSegment(const Point2& a, const Point2& b, Visit visit) const {
  const OccupancyGrid& g = *grid_;
  // Column by column: in each column the rows between the segment's heights at the column's two
  // sides.
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
      if (!visit(i, j)) return false;
    }
  }
  return true;
}

bool ClearanceMap::exactSweepFree(const Point2& a, const Point2& b, const Disc& disc) const {
  // 1. The cells the segment passes through, by the distance transform alone: a blocked cell ends
  //    the sweep (a step through a wall meets the wall's own cells), and free cells need nothing
  //    more. Most blocked steps end here, before any square is looked at. The cells in the band
  //    are kept (the first kKept of them; beyond that the walk is made again).
  constexpr int kKept = 64;
  std::int32_t near_i[kKept], near_j[kKept];
  int near = 0;
  const bool clear = forEachCellOnSegment(a, b, [&](int i, int j) {
    const Cell cell = classify(i, j, disc);
    if (cell == Cell::kNear) {
      if (near < kKept) near_i[near] = i, near_j[near] = j;
      ++near;
    }
    return cell != Cell::kBlocked;
  });
  if (!clear) return false;
  if (near == 0) return true;
  // 2. The cells in the band along the walls: the segment against the blocked squares within the
  //    radius of each, exactly. The window of squares looked at last is remembered, so a square is
  //    not tested twice for neighbour cells.
  const Segment segment{a, b};
  const int reach = disc.reach_cells;
  int last_i0 = 1, last_i1 = 0, last_j0 = 1, last_j1 = 0;
  auto clearOfSquares = [&](int i, int j) {
    const int i0 = i - reach, i1 = i + reach, j0 = j - reach, j1 = j + reach;
    const bool hit = anySquare(i0, i1, j0, j1, [&](int si, int sj) {
      const bool seen = si >= last_i0 && si <= last_i1 && sj >= last_j0 && sj <= last_j1;
      return !seen && segmentMeets(segment, grid_->square(si, sj), disc.radius);
    });
    last_i0 = i0, last_i1 = i1, last_j0 = j0, last_j1 = j1;
    return !hit;
  };
  if (near <= kKept) {
    for (int k = 0; k < near; ++k) {
      if (!clearOfSquares(near_i[k], near_j[k])) return false;
    }
    return true;
  }
  return forEachCellOnSegment(a, b, [&](int i, int j) {
    return classify(i, j, disc) != Cell::kNear || clearOfSquares(i, j);
  });
}

}  // namespace roomba_rrt::geometry
