// Ray casting against the room's closed shapes (ray_cast.h).
#include "roomba_rrt/sensors/ray_cast.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace roomba_rrt::sensors {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
/// Crossings of an x line and a y line nearer than this (m) pass (within rounding) through a
/// cell corner: both cells beside it are tested.
constexpr double kCornerSlack = 1e-9;
/// The same near a corner where a jump lands, in cells.
constexpr double kCornerCells = 1e-6;

/// The ray parameters at which it crosses the box's far x side and far y side (+inf along an
/// axis it does not move along): where a ray that is inside the box leaves it.
std::pair<double, double> exitTimes(const Ray& ray, const geometry::Rectangle& box) {
  const double tx = ray.dx > 0   ? (box.max_x - ray.origin.x) / ray.dx
                    : ray.dx < 0 ? (box.min_x - ray.origin.x) / ray.dx
                                 : kInf;
  const double ty = ray.dy > 0   ? (box.max_y - ray.origin.y) / ray.dy
                    : ray.dy < 0 ? (box.min_y - ray.origin.y) / ray.dy
                                 : kInf;
  return {tx, ty};
}

/// The clearance of every cell (ray_cast.h): an exact Chebyshev distance transform in two
/// passes over the 8-neighbourhood, cells outside the grid counting as blocked.
std::vector<std::uint8_t> chebyshevClearance(const geometry::OccupancyGrid& g) {
  const int w = g.width, h = g.height;
  std::vector<std::uint8_t> d(static_cast<std::size_t>(w) * h);
  const auto at = [&](int i, int j) -> int {
    return (i < 0 || j < 0 || i >= w || j >= h) ? 0 : d[static_cast<std::size_t>(j) * w + i];
  };
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      int v = g.blocked(i, j) ? 0 : 255;
      if (v)
        v = std::min(
            {v, at(i - 1, j) + 1, at(i - 1, j - 1) + 1, at(i, j - 1) + 1, at(i + 1, j - 1) + 1});
      d[static_cast<std::size_t>(j) * w + i] = static_cast<std::uint8_t>(v);
    }
  }
  for (int j = h - 1; j >= 0; --j) {
    for (int i = w - 1; i >= 0; --i) {
      int v = d[static_cast<std::size_t>(j) * w + i];
      if (v)
        v = std::min(
            {v, at(i + 1, j) + 1, at(i + 1, j + 1) + 1, at(i, j + 1) + 1, at(i - 1, j + 1) + 1});
      d[static_cast<std::size_t>(j) * w + i] = static_cast<std::uint8_t>(v);
    }
  }
  return d;
}

}  // namespace

double hitCircle(const Ray& ray, const geometry::Circle& circle) {
  const double ox = ray.origin.x - circle.center.x, oy = ray.origin.y - circle.center.y;
  const double c = ox * ox + oy * oy - circle.radius * circle.radius;
  if (c <= 0) return 0;                        // the origin is in the disc
  const double b = ox * ray.dx + oy * ray.dy;  // t² + 2bt + c = 0
  if (b >= 0) return kInf;                     // moving away from the centre
  const double disc = b * b - c;
  if (disc < 0) return kInf;
  return c / (-b + std::sqrt(disc));  // the nearer root, without cancellation
}

double hitRectangle(const Ray& ray, const geometry::Rectangle& box) {
  double t_near = 0, t_far = kInf;
  const auto slab = [&](double o, double d, double lo, double hi) {
    if (d == 0) {
      if (o < lo || o > hi) t_near = kInf;
      return;
    }
    double t0 = (lo - o) / d, t1 = (hi - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    t_near = std::max(t_near, t0);
    t_far = std::min(t_far, t1);
  };
  slab(ray.origin.x, ray.dx, box.min_x, box.max_x);
  slab(ray.origin.y, ray.dy, box.min_y, box.max_y);
  return t_near <= t_far ? t_near : kInf;
}

double leaveRectangle(const Ray& ray, const geometry::Rectangle& room) {
  const geometry::Point2& o = ray.origin;
  if (!(o.x > room.min_x && o.x < room.max_x && o.y > room.min_y && o.y < room.max_y)) return 0;
  const auto [tx, ty] = exitTimes(ray, room);
  return std::min(tx, ty);
}

RayCaster::RayCaster(const world::Room& room)
    : room_(room),
      walls_{room.origin.x, room.origin.y, room.origin.x + room.width,
             room.origin.y + room.height} {
  if (room_.map) clearance_ = chebyshevClearance(*room_.map);
}

double RayCaster::cast(const Ray& ray, double max_range,
                       const std::vector<geometry::Circle>& others) const {
  double limit = max_range;  // nothing nearer found yet
  bool found = false;
  const auto consider = [&](double t) {
    if (t <= limit) {
      limit = t;
      found = true;
    }
  };
  consider(leaveRectangle(ray, walls_));
  for (const geometry::Circle& c : room_.circles) consider(hitCircle(ray, c));
  for (const geometry::Rectangle& b : room_.rectangles) consider(hitRectangle(ray, b));
  for (const geometry::Circle& c : others) consider(hitCircle(ray, c));
  if (room_.map) consider(castMap(ray, limit));
  return found ? limit : kInf;
}

double RayCaster::castMap(const Ray& ray, double limit) const {
  const geometry::OccupancyGrid& g = *room_.map;
  const double res = g.resolution;
  const int si = ray.dx > 0 ? 1 : (ray.dx < 0 ? -1 : 0);
  const int sj = ray.dy > 0 ? 1 : (ray.dy < 0 ? -1 : 0);
  // Where the ray crosses the x (y) line that leaves column i (row j) in its direction, always
  // from the ray's own origin: no error builds up along the walk.
  // (Multiplied by the inverse: the order of the crossings is all the walk needs, within
  // rounding, which the corner test below covers; the distance returned is the square's own.)
  const double inv_x = 1 / ray.dx, inv_y = 1 / ray.dy;
  const double ox = g.origin.x + (si > 0) * res - ray.origin.x;
  const double oy = g.origin.y + (sj > 0) * res - ray.origin.y;
  const auto cross_x = [&](int i) { return si == 0 ? kInf : (ox + i * res) * inv_x; };
  const auto cross_y = [&](int j) { return sj == 0 ? kInf : (oy + j * res) * inv_y; };
  // A cell's clearance, 0 when it is blocked (outside the grid too): the walk reads this array
  // alone, not the grid's cells as well (one cache miss per new place, not two).
  const auto clearance = [&](int i, int j) {
    return g.inside(i, j) ? clearance_[static_cast<std::size_t>(j) * g.width + i] : 0;
  };
  // A blocked cell the ray touches (its closed square), or +inf: rounding in the cell a jump
  // lands in may name a neighbour the ray only passes by.
  const auto touch = [&](int i, int j) {
    return clearance(i, j) == 0 ? hitRectangle(ray, g.square(i, j)) : kInf;
  };
  // The squares round cell (i, j), which may touch the ray where it is: at the origin, or where
  // a jump lands, a point that rounding may have put in any of the cells that share it.
  const auto touch_around = [&](int i, int j) {
    double t = kInf;
    if (clearance(i, j) >= 2) return t;  // all nine are free
    for (int b = j - 1; b <= j + 1; ++b) {
      for (int a = i - 1; a <= i + 1; ++a) t = std::min(t, touch(a, b));
    }
    return t;
  };
  const double inv_res = 1 / res;
  int i = g.column(ray.origin.x), j = g.row(ray.origin.y);
  double best = touch_around(i, j);
  for (;;) {
    const int k = clearance(i, j);
    if (k == 0) {
      best = std::min(best, touch(i, j));
      if (best < kInf) return best <= limit ? best : kInf;
    } else if (k >= 3) {
      // Every cell within k − 1 of (i, j) is free: leave that block in one step, to the cell of
      // the block where the ray leaves it (worth it from two cells on).
      const int ei = i + si * (k - 1), ej = j + sj * (k - 1);  // its last column and row
      const double tx = cross_x(ei), ty = cross_y(ej);
      const double t = std::min(tx, ty);
      if (best <= t || t > limit) return best <= limit ? best : kInf;
      // The landing point's other coordinate, in cells: near a whole number, the point is near
      // a cell corner, where rounding may have picked the wrong one of the cells that share it.
      const double cells = tx <= ty ? (ray.origin.y + t * ray.dy - g.origin.y) * inv_res
                                    : (ray.origin.x + t * ray.dx - g.origin.x) * inv_res;
      const int across = std::clamp(static_cast<int>(std::floor(cells)), (tx <= ty ? j : i) - k + 1,
                                    (tx <= ty ? j : i) + k - 1);
      const int ni = tx <= ty ? ei : across;
      const int nj = tx <= ty ? (ty <= tx ? ej : across) : ej;
      if (ni != i || nj != j) {
        i = ni;
        j = nj;
        // Away from a corner the walk's next crossing reaches the one square the point touches.
        if (tx == ty || std::abs(cells - std::round(cells)) < kCornerCells) {
          best = std::min(best, touch_around(i, j));
        }
        continue;
      }
    }
    // A ray along a grid line touches the squares on both sides of it.
    if (sj == 0) best = std::min({best, touch(i, j - 1), touch(i, j + 1)});
    if (si == 0) best = std::min({best, touch(i - 1, j), touch(i + 1, j)});
    const double tx = cross_x(i), ty = cross_y(j);
    const double t = std::min(tx, ty);
    if (best <= t) return best <= limit ? best : kInf;
    if (t > limit) return kInf;
    if (std::abs(tx - ty) <= kCornerSlack) {
      // Through a corner (or within rounding of one): the two squares that may only touch the
      // ray there count too, as far as the square's own test says they touch it.
      best = std::min({best, touch(i + si, j), touch(i, j + sj)});
    }
    // One cell at a time, through a corner too (the cell beside it is then visited, which the
    // ray touches there); without a branch: the order of crossings is hard to predict.
    const bool step_x = tx <= ty;
    i += step_x ? si : 0;
    j += step_x ? 0 : sj;
  }
}

}  // namespace roomba_rrt::sensors
