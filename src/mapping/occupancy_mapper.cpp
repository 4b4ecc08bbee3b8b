#include "roomba_rrt/mapping/occupancy_mapper.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "roomba_rrt/util/require.h"

namespace roomba_rrt::mapping {
namespace {

/// A hit's end point is moved this far along its ray (this much of its range, plus as many
/// metres) before its cell is taken: the ray ends on the edge of the obstacle's cell, and the
/// rounding of a float range (2^-24 of it) must not put it in the free cell before it.
constexpr double kIntoHit = 1e-6;

/// Liang–Barsky: clips the segment p0 + t (d) for t in [t0, t1] to the box [0, w] × [0, h].
/// Returns false when nothing of it is inside.
bool clip(double x0, double y0, double dx, double dy, double w, double h, double& t0, double& t1) {
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {x0, w - x0, y0, h - y0};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0) {
      if (q[k] < 0) return false;
      continue;
    }
    const double r = q[k] / p[k];
    if (p[k] < 0) {
      t0 = std::max(t0, r);
    } else {
      t1 = std::min(t1, r);
    }
  }
  return t0 <= t1;
}

}  // namespace

void validate(const MapperOptions& o) {
  using util::requireInRange;
  requireInRange("resolution", o.resolution, MapperLimits::kMinResolution,
                 MapperLimits::kMaxResolution, "m");
  const double c = MapperLimits::kMaxCoordinate;
  requireInRange("xmin", o.xmin, -c, c, "m");
  requireInRange("ymin", o.ymin, -c, c, "m");
  requireInRange("xmax", o.xmax, -c, c, "m");
  requireInRange("ymax", o.ymax, -c, c, "m");
  util::require(o.xmax > o.xmin, "xmax", "> xmin (" + util::show(o.xmin) + ")", o.xmax);
  util::require(o.ymax > o.ymin, "ymax", "> ymin (" + util::show(o.ymin) + ")", o.ymax);
  requireInRange("max_cells", o.max_cells, 1, MapperLimits::kMaxCells);
  const double cells =
      std::ceil((o.xmax - o.xmin) / o.resolution) * std::ceil((o.ymax - o.ymin) / o.resolution);
  if (cells > static_cast<double>(o.max_cells)) {
    throw util::InvalidInput("xmin, ymin, xmax, ymax",
                             "the region has " + util::show(cells) + " cells of " +
                                 util::show(o.resolution) + " m; at most " +
                                 std::to_string(o.max_cells) + " (max_cells)");
  }
  util::requirePositive("max_range", o.max_range);
  const double l = MapperLimits::kMaxLogOdds;
  util::require(o.log_odds_occupied > 0 && o.log_odds_occupied <= l, "log_odds_occupied",
                "in (0, " + util::show(l) + "]", o.log_odds_occupied);
  util::require(o.log_odds_free < 0 && o.log_odds_free >= -l, "log_odds_free",
                "in [" + util::show(-l) + ", 0)", o.log_odds_free);
  util::requirePositive("log_odds_limit", o.log_odds_limit, l);
  util::require(o.occupied_threshold > 0 && o.occupied_threshold < 1, "occupied_threshold",
                "in (0, 1)", o.occupied_threshold);
}

double firstRayAngle(double heading, const ScanView& scan) {
  return std::remainder(heading, 2 * M_PI) + std::remainder(scan.angle_min, 2 * M_PI);
}

std::string checkScan(const ScanView& s) {
  std::ostringstream why;
  const auto finite = [&why](const char* field, double v) {
    if (std::isfinite(v)) return true;
    why << field << ": must be finite, got " << v;
    return false;
  };
  if (s.count == 0 || !s.ranges) return "ranges: empty";
  if (!finite("angle_min", s.angle_min) || !finite("angle_max", s.angle_max) ||
      !finite("angle_increment", s.angle_increment) || !finite("range_min", s.range_min) ||
      !finite("range_max", s.range_max)) {
    return why.str();
  }
  if (s.range_min < 0) {
    why << "range_min: must be ≥ 0, got " << s.range_min;
  } else if (s.range_max <= s.range_min) {
    why << "range_max: must be > range_min (" << s.range_min << "), got " << s.range_max;
  } else if (s.count > 1) {
    const double n = static_cast<double>(s.count - 1);
    const double last = s.angle_min + n * s.angle_increment;
    const double tolerance = std::max(1e-4, 0.1 * std::abs(s.angle_increment));
    if (s.angle_increment == 0) {
      why << "angle_increment: 0 for " << s.count << " rays";
    } else if (std::abs(last - s.angle_max) > tolerance) {
      why << "angle_max: " << s.angle_max << " is not angle_min + (" << s.count
          << " - 1) * angle_increment = " << last << " (the scan's angles do not add up)";
    } else if (std::abs(n * s.angle_increment) > 2 * M_PI + tolerance) {
      why << "angle_increment: " << s.count << " rays of " << s.angle_increment
          << " rad span more than a turn";
    }
  }
  return why.str();
}

OccupancyMapper::OccupancyMapper(const MapperOptions& options) : options_(options) {
  validate(options_);
  width_ = static_cast<int>(std::ceil((options_.xmax - options_.xmin) / options_.resolution));
  height_ = static_cast<int>(std::ceil((options_.ymax - options_.ymin) / options_.resolution));
  origin_ = {options_.xmin, options_.ymin};
  log_odds_.assign(static_cast<std::size_t>(width_) * height_, kUnobserved);
  const auto fixed = [](double v) { return static_cast<int>(std::lround(kLogOddsScale * v)); };
  occupied_ = std::max(1, fixed(options_.log_odds_occupied));
  free_ = std::min(-1, fixed(options_.log_odds_free));
  limit_ = std::max(1, fixed(options_.log_odds_limit));
}

void OccupancyMapper::cover(double x0, double y0, double x1, double y1) {
  const double r = options_.resolution;
  // Cells to add on each side (whole cells: the lattice stays the same).
  const auto need = [r](double d) { return d > 0 ? std::ceil(d / r) : 0.0; };
  const double cells[4] = {need(origin_.x - x0), need(origin_.y - y0),
                           need(x1 - (origin_.x + width_ * r)),
                           need(y1 - (origin_.y + height_ * r))};
  if (cells[0] + cells[1] + cells[2] + cells[3] == 0) return;
  for (const double n : cells) {
    if (!(n <= MapperLimits::kMaxCells)) return;  // far beyond any map (NaN too): not grown
  }
  long long left = static_cast<long long>(cells[0]), bottom = static_cast<long long>(cells[1]);
  long long right = static_cast<long long>(cells[2]), top = static_cast<long long>(cells[3]);
  // Grow by a quarter of the map at least on a side that grows: a robot driving out of the map
  // copies it a few times, not at every scan.
  const auto grow = [](long long n, int size) { return n ? std::max<long long>(n, size / 4) : 0; };
  left = grow(left, width_);
  right = grow(right, width_);
  bottom = grow(bottom, height_);
  top = grow(top, height_);
  const long long w = width_ + left + right, h = height_ + bottom + top;
  if (w > MapperLimits::kMaxCells || h > MapperLimits::kMaxCells || w * h > options_.max_cells) {
    return;  // the part of the scan inside is still used
  }
  std::vector<std::int16_t> log_odds(static_cast<std::size_t>(w * h), kUnobserved);
  for (int j = 0; j < height_; ++j) {
    const std::size_t from = index(0, j);
    const std::size_t to = static_cast<std::size_t>((j + bottom) * w + left);
    std::copy_n(log_odds_.begin() + from, width_, log_odds.begin() + to);
  }
  log_odds_.swap(log_odds);
  // The origin from the first one and a whole number of cells, never by repeated subtraction.
  const long long shift_x = std::llround((options_.xmin - origin_.x) / r) + left;
  const long long shift_y = std::llround((options_.ymin - origin_.y) / r) + bottom;
  origin_ = {options_.xmin - shift_x * r, options_.ymin - shift_y * r};
  width_ = static_cast<int>(w);
  height_ = static_cast<int>(h);
}

void OccupancyMapper::add(std::size_t k, int delta) {
  const int v = log_odds_[k];
  log_odds_[k] = static_cast<std::int16_t>(
      std::clamp((v > limit_ ? 0 : v) + delta, -limit_, limit_));  // kUnobserved counts as 0
}

void OccupancyMapper::traceRay(double x0, double y0, double x1, double y1, bool hit) {
  const double dx = x1 - x0, dy = y1 - y0;
  double t0 = 0, t1 = 1;
  if (!clip(x0, y0, dx, dy, width_, height_, t0, t1)) return;
  hit = hit && t1 == 1;  // a hit outside the grid is not in it
  const auto cell = [](double u, int size) {
    return std::clamp(static_cast<int>(std::floor(u)), 0, size - 1);
  };
  const int i = cell(x0 + t0 * dx, width_), j = cell(y0 + t0 * dy, height_);
  const int ie = cell(x0 + t1 * dx, width_), je = cell(y0 + t1 * dy, height_);
  // Amanatides & Woo: t (along the whole segment) at the next vertical and horizontal cell edge.
  const double delta_i = dx != 0 ? 1 / std::abs(dx) : HUGE_VAL;
  const double delta_j = dy != 0 ? 1 / std::abs(dy) : HUGE_VAL;
  double next_i = dx > 0 ? (i + 1 - x0) / dx : dx < 0 ? (x0 - i) / -dx : HUGE_VAL;
  double next_j = dy > 0 ? (j + 1 - y0) / dy : dy < 0 ? (y0 - j) / -dy : HUGE_VAL;
  // Every step moves one cell towards the end cell: exactly |ie − i| + |je − j| steps, whatever
  // the rounding of the edge crossings, and the walk ends in the end cell.
  int left_i = std::abs(ie - i), left_j = std::abs(je - j);
  const std::ptrdiff_t step_i = dx > 0 ? 1 : -1, step_j = dy > 0 ? width_ : -width_;
  std::size_t k = index(i, j);
  std::int16_t* const cells = log_odds_.data();
  const int free = free_, limit = limit_;
  for (int n = left_i + left_j; n > 0; --n) {
    const int v = cells[k];
    cells[k] = static_cast<std::int16_t>(std::max((v > limit ? 0 : v) + free, -limit));
    if (left_j == 0 || (left_i != 0 && next_i < next_j)) {
      k += step_i;
      next_i += delta_i;
      --left_i;
    } else {
      k += step_j;
      next_j += delta_j;
      --left_j;
    }
  }
  add(k, hit ? occupied_ : free);
}

std::string OccupancyMapper::addScan(const robot::Pose2D& pose, const ScanView& scan) {
  std::string why = checkScan(scan);
  if (!why.empty()) return why;
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.theta)) {
    return "pose: not finite";
  }
  if (std::abs(pose.x) > MapperLimits::kMaxCoordinate ||
      std::abs(pose.y) > MapperLimits::kMaxCoordinate) {
    return "pose: (" + util::show(pose.x) + ", " + util::show(pose.y) + ") is more than " +
           util::show(MapperLimits::kMaxCoordinate) + " m from the origin";
  }
  const double reach = trustedRange(scan);
  // The cells the scan can touch: the map grows to hold them first.
  double x0 = pose.x, y0 = pose.y, x1 = pose.x, y1 = pose.y;
  struct End {
    double x, y;
    bool hit;
  };
  thread_local std::vector<End> ends;
  ends.clear();
  // The rays' directions by turning the first by the increment (no sine per ray): the error
  // after 10^5 rays is about 10^-11 rad.
  const double first = firstRayAngle(pose.theta, scan);
  const double turn_c = std::cos(scan.angle_increment), turn_s = std::sin(scan.angle_increment);
  double c = std::cos(first), s = std::sin(first);
  for (std::size_t k = 0; k < scan.count; ++k) {
    if (k > 0) {
      const double next_c = c * turn_c - s * turn_s;
      s = s * turn_c + c * turn_s;
      c = next_c;
    }
    const double r = scan.ranges[k];
    bool hit = true;
    double length = r;
    if (isReturn(r, scan)) {
      length += kIntoHit * (1 + length);
    } else if (r == HUGE_VAL || (std::isfinite(r) && r > reach && r <= scan.range_max)) {
      length = reach;  // no return within range_max (REP 117), or beyond what is trusted
      hit = false;
    } else {
      continue;  // NaN, −inf (too near to tell) or out of the scan's own range
    }
    const End e{pose.x + length * c, pose.y + length * s, hit};
    x0 = std::min(x0, e.x);
    y0 = std::min(y0, e.y);
    x1 = std::max(x1, e.x);
    y1 = std::max(y1, e.y);
    ends.push_back(e);
  }
  cover(x0, y0, x1, y1);
  const double inv = 1 / options_.resolution;
  const double sx = (pose.x - origin_.x) * inv, sy = (pose.y - origin_.y) * inv;
  for (const End& e : ends) {
    traceRay(sx, sy, (e.x - origin_.x) * inv, (e.y - origin_.y) * inv, e.hit);
  }
  ++scans_;
  return "";
}

void OccupancyMapper::markOccupied(const geometry::Point2& p) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
  cover(p.x, p.y, p.x, p.y);
  const double u = std::floor((p.x - origin_.x) / options_.resolution);
  const double v = std::floor((p.y - origin_.y) / options_.resolution);
  if (!(u >= 0 && v >= 0 && u < width_ && v < height_)) return;  // beyond max_cells
  add(index(static_cast<int>(u), static_cast<int>(v)), occupied_);
}

void OccupancyMapper::addBump(const robot::Pose2D& pose, double radius,
                              const robot::BumperState& bumper) {
  if (!bumper.pressed || !(radius >= 0)) return;
  // Just beyond the bumper's edge: the middle of the cell there.
  const double reach = radius + options_.resolution / 2;
  const auto mark = [&](double bearing) {
    const double a = pose.theta + bearing;
    markOccupied({pose.x + reach * std::cos(a), pose.y + reach * std::sin(a)});
  };
  if (bumper.left && bumper.right) {
    mark(0);
  } else if (bumper.left) {
    mark(M_PI / 4);
  } else if (bumper.right) {
    mark(-M_PI / 4);
  }
}

void OccupancyMapper::grid(geometry::OccupancyGrid& out) const {
  out.width = width_;
  out.height = height_;
  out.resolution = options_.resolution;
  out.origin = origin_;
  out.cells.resize(log_odds_.size());
  const double p = options_.occupied_threshold;
  const double threshold = kLogOddsScale * std::log(p / (1 - p));
  for (std::size_t k = 0; k < log_odds_.size(); ++k) {
    out.cells[k] = log_odds_[k] == kUnobserved ? geometry::OccupancyGrid::kUnknown
                   : log_odds_[k] > threshold  ? geometry::OccupancyGrid::kOccupied
                                               : geometry::OccupancyGrid::kFree;
  }
}

geometry::OccupancyGrid OccupancyMapper::grid() const {
  geometry::OccupancyGrid out;
  grid(out);
  return out;
}

}  // namespace roomba_rrt::mapping
