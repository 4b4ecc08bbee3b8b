// Ray casting against the room's closed shapes (ray_cast.h).
#include "roomba_rrt/sensors/ray_cast.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace roomba_rrt::sensors {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
/// How far (in cells) the runs of cells tested against a ray reach beyond it on every side: far
/// more than the rounding of the walk's arithmetic (about 1e-12 cell on a map of 10^4 cells),
/// so that every square the ray touches is among them; a square it only comes this near is
/// intersected and found not touched.
constexpr double kSlackCells = 1e-9;
constexpr int kPad = BlockedBits::kPadCells;
/// Fixed point for the walk's u (cells): u · 2^32, exact to add.
constexpr double kFixedOne = 4294967296.0;
/// The slack of kSlackCells in fixed point, for a run's ends: 2^12 units (about 1e-6 cell), far
/// more than the first crossing's rounding (one unit); each increment adds less than one more.
constexpr std::int64_t kFixedSlack = std::int64_t{1} << 12;

/// floor(x) for x > −kPad (a cast truncates towards zero; without SSE4.1 std::floor is a call).
int floorAbove(double x) { return static_cast<int>(x + kPad) - kPad; }
std::int64_t fixedPoint(double u) { return static_cast<std::int64_t>((u + kPad) * kFixedOne); }
int cellOf(std::int64_t fixed) { return static_cast<int>(fixed >> 32) - kPad; }

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
  if (room_.map) {
    rows_ = BlockedBits(*room_.map);
    columns_ = rows_.transposed();
    inv_resolution_ = 1 / room_.map->resolution;
  }
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

// The map walk. Cells are closed squares, so the blocked square the ray meets first is the least
// of hitRectangle over every blocked square it touches. The walk finds that set line by line:
// with u the ray's main axis (x when |dx| ≥ |dy|) and v the other, the cells of line v (a row for
// u = x) that the ray touches are a run between where it crosses the lines v and v + 1, and one
// word of BlockedBits holds the run's blocked cells (57 at a time). Runs are widened by a slack,
// so that rounding never loses a square the ray touches (an extra one is intersected and
// missed). Lines are visited in the ray's order and a line's cells in its order, so the first
// square touched is the nearest: the ray enters a square no sooner than it leaves the one before
// it, in hitRectangle's own rounding too (both times are the same quotient for their shared
// side).

double RayCaster::castMap(const Ray& ray, double limit) const {
  const geometry::OccupancyGrid& g = *room_.map;
  // The origin in cells.
  const double px = (ray.origin.x - g.origin.x) * inv_resolution_;
  const double py = (ray.origin.y - g.origin.y) * inv_resolution_;
  // On the grid's edge or beyond it, the origin is in a square beyond the grid (blocked).
  if (!(px > 0 && px < g.width && py > 0 && py < g.height)) return 0;
  if (!(std::isfinite(ray.dx) && std::isfinite(ray.dy) && limit >= 0)) return kInf;
  if (std::abs(ray.dx) >= std::abs(ray.dy)) return walk<true>(ray, px, py, ray.dx, ray.dy, limit);
  return walk<false>(ray, py, px, ray.dy, ray.dx, limit);
}

template <bool kAlongX>
double RayCaster::walk(const Ray& ray, double pu, double pv, double du, double dv,
                       double limit) const {
  // One version per direction: the steps' signs are constants in the loop.
  if (dv == 0) {
    return du > 0 ? walkAlongLine<kAlongX, 1>(ray, pu, pv, limit)
                  : walkAlongLine<kAlongX, -1>(ray, pu, pv, limit);
  }
  if (du > 0) {
    return dv > 0 ? walkAcrossLines<kAlongX, 1, 1>(ray, pu, pv, du, dv, limit)
                  : walkAcrossLines<kAlongX, 1, -1>(ray, pu, pv, du, dv, limit);
  }
  return dv > 0 ? walkAcrossLines<kAlongX, -1, 1>(ray, pu, pv, du, dv, limit)
                : walkAcrossLines<kAlongX, -1, -1>(ray, pu, pv, du, dv, limit);
}

template <bool kAlongX, int kSu>
double RayCaster::walkAlongLine(const Ray& ray, double pu, double pv, double limit) const {
  const BlockedBits& bits = kAlongX ? rows_ : columns_;
  // The ray's cells along u, as far as one cell into the border.
  const double cells = std::min(limit * inv_resolution_, bits.length() + 2.0);
  const double end = pu + kSu * cells;
  const int a = floorAbove(std::max(std::min(pu, end), -1.0) - kSlackCells);
  const int b = floorAbove(std::min(std::max(pu, end), bits.length() + 1.0) + kSlackCells);
  // On the line between two rows it touches the cells of both.
  double best = kInf;
  for (int v = floorAbove(pv - kSlackCells); v <= floorAbove(pv + kSlackCells); ++v) {
    best = std::min(best, firstInRun<kAlongX, kSu>(ray, v, a, b));
  }
  return best <= limit ? best : kInf;
}

template <bool kAlongX, int kSu, int kSv>
double RayCaster::walkAcrossLines(const Ray& ray, double pu, double pv, double du, double dv,
                                  double limit) const {
  const BlockedBits& bits = kAlongX ? rows_ : columns_;
  // The ray's length in cells, no farther along u than one cell into the border.
  const double cells =
      std::min(limit * inv_resolution_, (kSu > 0 ? bits.length() + 1 - pu : pu + 1) / std::abs(du));
  const double u_end = pu + cells * du, v_end = pv + cells * dv;
  // The lines it crosses, first to last: with the slack, the one behind a line it starts on and
  // one it only just reaches; the border's last line at most.
  const int v0 = floorAbove(pv - kSv * kSlackCells);
  const int v1 = kSv > 0 ? std::min(floorAbove(v_end + kSlackCells), bits.lines() + 1)
                         : std::max(floorAbove(v_end - kSlackCells), -2);
  // Where it crosses the lines between them, in fixed point: the first from the origin, the next
  // ones by adding `step` (exact; the step's rounding is less than a unit per line). A step longer
  // than the line has no second crossing on the ray and is capped.
  const std::int64_t start = fixedPoint(pu), end = fixedPoint(u_end);
  const double u_per_v = du / dv;
  const std::int64_t step =
      kSu * static_cast<std::int64_t>(std::min(std::abs(u_per_v), bits.length() + 4.0) * kFixedOne);
  const std::int64_t slack = kFixedSlack + (v1 - v0) * kSv;
  const auto within = [&](std::int64_t u) {
    return kSu > 0 ? std::clamp(u, start, end) : std::clamp(u, end, start);
  };
  const std::uint8_t* line = bits.line(v0);
  const std::ptrdiff_t stride = kSv * bits.stride();
  // The nearest square the ray touches in the run of line v from u = in to u = out.
  const auto hit = [&](int v, std::int64_t in, std::int64_t out) {
    const int a = cellOf((kSu > 0 ? in : out) - slack), b = cellOf((kSu > 0 ? out : in) + slack);
    if (b - a > 56) return firstInRun<kAlongX, kSu>(ray, v, a, b);
    const std::uint64_t blocked = BlockedBits::cells(line, a, b - a + 1);
    return blocked ? firstOfBits<kAlongX, kSu>(ray, v, a, blocked) : kInf;
  };
  int v = v0;
  std::int64_t in = start;
  double t = kInf;
  if (v0 != v1) {
    const double first = pu + ((kSv > 0 ? v0 + 1 : v0) - pv) * u_per_v;
    std::int64_t cross = fixedPoint(std::clamp(first, -1.0, bits.length() + 1.0));
    const std::int64_t out = within(cross);
    t = hit(v, in, out);
    in = out;
    for (v += kSv, line += stride; t == kInf && v != v1; v += kSv, line += stride) {
      cross += step;
      t = hit(v, in, cross);
      in = cross;
    }
    in = within(in);
  }
  if (t == kInf) t = hit(v, in, end);
  return t <= limit ? t : kInf;
}

template <bool kAlongX, int kSu>
double RayCaster::firstInRun(const Ray& ray, int v, int a, int b) const {
  // 57 cells at a time (what one word holds after its shift), in the ray's order.
  const std::uint8_t* line = (kAlongX ? rows_ : columns_).line(v);
  for (;;) {
    const int lo = kSu > 0 ? a : std::max(a, b - 56), hi = kSu > 0 ? std::min(b, a + 56) : b;
    const std::uint64_t blocked = BlockedBits::cells(line, lo, hi - lo + 1);
    if (blocked) {
      const double t = firstOfBits<kAlongX, kSu>(ray, v, lo, blocked);
      if (t < kInf) return t;
    }
    if (kSu > 0 ? hi == b : lo == a) return kInf;
    (kSu > 0 ? a : b) = kSu > 0 ? hi + 1 : lo - 1;
  }
}

template <bool kAlongX, int kSu>
double RayCaster::firstOfBits(const Ray& ray, int v, int u0, std::uint64_t blocked) const {
  // In the ray's order: the first square it touches is the nearest.
  while (blocked) {
    const int k = kSu > 0 ? __builtin_ctzll(blocked) : 63 - __builtin_clzll(blocked);
    blocked &= ~(std::uint64_t{1} << k);
    const double t = hitCell<kAlongX>(ray, u0 + k, v);
    if (t < kInf) return t;
  }
  return kInf;
}

template <bool kAlongX>
double RayCaster::hitCell(const Ray& ray, int u, int v) const {
  return hitRectangle(ray, kAlongX ? room_.map->square(u, v) : room_.map->square(v, u));
}

}  // namespace roomba_rrt::sensors
