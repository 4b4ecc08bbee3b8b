#include "roomba_rrt/exploration/built_map.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "roomba_rrt/mapping/sensor_scan.h"

namespace roomba_rrt::exploration {
namespace {

/// Cells of `resolution` 10 m round the start, or over the known map's extent (its lattice from
/// its corner).
mapping::MapperOptions mapperOptions(const robot::Pose2D& start, double resolution,
                                     const geometry::OccupancyGrid* known) {
  mapping::MapperOptions options;
  options.resolution = resolution;
  options.xmin = start.x - 5;
  options.xmax = start.x + 5;
  options.ymin = start.y - 5;
  options.ymax = start.y + 5;
  if (known) {
    const geometry::Rectangle extent = known->extent();
    options.xmin = extent.min_x;
    options.xmax = extent.max_x;
    options.ymin = extent.min_y;
    options.ymax = extent.max_y;
  }
  return options;
}

/// The value of `known` over the square `s`: occupied where an occupied cell's interior meets
/// it, free where only free cells' do, else unknown (off the map too).
std::int8_t knownOver(const geometry::OccupancyGrid& known, const geometry::Rectangle& s) {
  const double r = known.resolution;
  const int i0 = static_cast<int>(std::floor((s.min_x - known.origin.x) / r + 1e-9));
  const int j0 = static_cast<int>(std::floor((s.min_y - known.origin.y) / r + 1e-9));
  const int i1 = static_cast<int>(std::ceil((s.max_x - known.origin.x) / r - 1e-9)) - 1;
  const int j1 = static_cast<int>(std::ceil((s.max_y - known.origin.y) / r - 1e-9)) - 1;
  bool all_free = true;
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      if (!known.inside(i, j)) {
        all_free = false;
        continue;
      }
      const std::int8_t v = known.at(i, j);
      if (v == geometry::OccupancyGrid::kOccupied) return v;
      all_free = all_free && v == geometry::OccupancyGrid::kFree;
    }
  }
  return all_free ? geometry::OccupancyGrid::kFree : geometry::OccupancyGrid::kUnknown;
}

}  // namespace

BuiltMap::BuiltMap(const world::RobotSpec& robot,
                   std::shared_ptr<const geometry::OccupancyGrid> known, int fine_split)
    : robot_(robot),
      mapper_(mapperOptions(robot.initial_pose, kResolution, known.get())),
      lattice_(mapper_.origin()) {
  footprints_.push_back({robot_.initial_pose.x, robot_.initial_pose.y});
  if (fine_split > 1) {
    fine_ = std::make_unique<mapping::OccupancyMapper>(
        mapperOptions(robot.initial_pose, kResolution / fine_split, known.get()));
  }
  if (!known) return;
  prior_width_ = mapper_.width();
  prior_height_ = mapper_.height();
  prior_.resize(static_cast<std::size_t>(prior_width_) * prior_height_);
  const geometry::OccupancyGrid lattice = mapper_.grid();  // for its cells' squares
  for (int j = 0; j < prior_height_; ++j) {
    for (int i = 0; i < prior_width_; ++i) {
      prior_[static_cast<std::size_t>(j) * prior_width_ + i] =
          knownOver(*known, lattice.square(i, j));
    }
  }
}

std::int8_t BuiltMap::prior(std::int64_t gi, std::int64_t gj) const {
  if (gi < 0 || gj < 0 || gi >= prior_width_ || gj >= prior_height_) {
    return geometry::OccupancyGrid::kUnknown;
  }
  return prior_[static_cast<std::size_t>(gj) * prior_width_ + gi];
}

bool BuiltMap::seenOccupied(const geometry::Point2& p) const {
  const double resolution = mapper_.resolution();
  return hits_.count(
      cellKey(static_cast<std::int64_t>(std::floor((p.x - lattice_.x) / resolution)),
              static_cast<std::int64_t>(std::floor((p.y - lattice_.y) / resolution))));
}

std::string BuiltMap::addScan(const robot::Pose2D& sensor, const mapping::ScanView& scan) {
  std::string why = mapper_.addScan(sensor, scan);
  if (why.empty()) {
    if (fine_) fine_->addScan(sensor, scan);
    markHits(sensor, scan);
  }
  return why;
}

void BuiltMap::addBump(const robot::Pose2D& pose, const robot::BumperState& bumper) {
  mapper_.addBump(pose, robot_.radius, bumper);
  if (fine_) fine_->addBump(pose, robot_.radius, bumper);
  if (prior_.empty() || !bumper.pressed) return;
  // On a known map the bumped cell is a hit (what it pressed, a hair inside it), so that the
  // known floor there is not floor any more.
  const double side = bumper.left == bumper.right ? 0.0 : bumper.left ? M_PI / 4 : -M_PI / 4;
  const double r = robot_.radius + kInside;
  const double resolution = mapper_.resolution();
  const double x = pose.x + r * std::cos(pose.theta + side);
  const double y = pose.y + r * std::sin(pose.theta + side);
  hits_.insert(cellKey(static_cast<std::int64_t>(std::floor((x - lattice_.x) / resolution)),
                       static_cast<std::int64_t>(std::floor((y - lattice_.y) / resolution))));
}

void BuiltMap::markHits(const robot::Pose2D& sensor, const mapping::ScanView& scan) {
  // The cells of `cell` m holding the points from a to b (sampled every fifth of a cell) into
  // `hits`.
  auto mark = [&](const geometry::Point2& a, const geometry::Point2& b, double cell,
                  std::unordered_set<std::int64_t>& hits) {
    const int samples =
        std::max(1, static_cast<int>(std::ceil(geometry::distance(a, b) / (0.2 * cell))));
    for (int s = 1; s <= samples; ++s) {
      const double t = static_cast<double>(s) / samples;
      hits.insert(cellKey(
          static_cast<std::int64_t>(std::floor((a.x + t * (b.x - a.x) - lattice_.x) / cell)),
          static_cast<std::int64_t>(std::floor((a.y + t * (b.y - a.y) - lattice_.y) / cell))));
    }
  };
  bool previous_hit = false;
  geometry::Point2 previous;
  const double first = mapping::firstRayAngle(sensor.theta, scan);
  for (std::size_t k = 0; k < scan.count; ++k) {
    const double range = scan.ranges[k];
    // The rays the mapper counts as hits only: no return (+inf, or beyond what it trusts) and
    // none to trust (NaN, below range_min) are not.
    if (!mapper_.isReturn(range, scan)) {
      previous_hit = false;
      continue;
    }
    // A hair beyond the return, inside what it hit.
    const double angle = first + static_cast<double>(k) * scan.angle_increment;
    const double r = range + kInside;
    const geometry::Point2 hit{sensor.x + r * std::cos(angle), sensor.y + r * std::sin(angle)};
    // Two neighbouring returns close together lie on one obstacle: the chord between them
    // lies inside it (on a wall, along it), and so does every cell it crosses, among them the
    // cells the obstacle's edge crosses between the two returns, where no ray ended.
    const geometry::Point2 from =
        previous_hit && geometry::distance(previous, hit) <= kChord ? previous : hit;
    mark(from, hit, mapper_.resolution(), hits_);
    if (fine_) mark(from, hit, fine_->resolution(), fine_hits_);
    previous = hit;
    previous_hit = true;
  }
}

void BuiltMap::markGrid(geometry::OccupancyGrid& grid, bool strict) const {
  for (int j = 0; j < grid.height; ++j) {
    for (int i = 0; i < grid.width; ++i) {
      std::int8_t& cell = grid.cells[static_cast<std::size_t>(j) * grid.width + i];
      // Strict: free only where the rays said so clearly; a cell an obstacle's edge crosses gets
      // free evidence from the rays that pass its free part and hits from those that end in it,
      // and the robot plans as close to a free cell as to the floor.
      if (strict && cell == geometry::OccupancyGrid::kFree &&
          mapper_.logOdds(i, j) > kClearlyFree) {
        cell = geometry::OccupancyGrid::kOccupied;
      }
      const std::int64_t gi = std::llround((grid.origin.x - lattice_.x) / grid.resolution) + i;
      const std::int64_t gj = std::llround((grid.origin.y - lattice_.y) / grid.resolution) + j;
      if (!prior_.empty()) {
        // The known map: its floor is floor unless the mapper holds the cell more likely
        // occupied than not; its walls are walls.
        const std::int8_t known = prior(gi, gj);
        if (known == geometry::OccupancyGrid::kFree) cell = geometry::OccupancyGrid::kFree;
        if (known == geometry::OccupancyGrid::kOccupied) cell = geometry::OccupancyGrid::kOccupied;
      }
      // A ray ended in it: an obstacle's edge crosses it, however many rays passed its free part.
      if (hits_.count(cellKey(gi, gj))) cell = geometry::OccupancyGrid::kOccupied;
    }
  }
}

void BuiltMap::markFootprints(geometry::OccupancyGrid& grid) const {
  // Where the robot stood is floor: every cell wholly under its disc, whatever the map says
  // (the cells it marked while it was seen from afar), and the unknown cells its disc reaches
  // into (its lidar starts range_min from its centre).
  const int r = static_cast<int>(std::ceil(robot_.radius / grid.resolution));
  const double r2 = robot_.radius * robot_.radius;
  for (const geometry::Point2& p : footprints_) {
    const int ci = grid.column(p.x), cj = grid.row(p.y);
    for (int j = cj - r; j <= cj + r; ++j) {
      for (int i = ci - r; i <= ci + r; ++i) {
        if (!grid.inside(i, j)) continue;
        const geometry::Rectangle s = grid.square(i, j);
        const double nx = std::max({s.min_x - p.x, 0.0, p.x - s.max_x});
        const double ny = std::max({s.min_y - p.y, 0.0, p.y - s.max_y});
        const double fx = std::max(p.x - s.min_x, s.max_x - p.x);
        const double fy = std::max(p.y - s.min_y, s.max_y - p.y);
        std::int8_t& cell = grid.cells[static_cast<std::size_t>(j) * grid.width + i];
        const bool under = fx * fx + fy * fy < r2;
        const bool reached = nx * nx + ny * ny < r2 && cell == geometry::OccupancyGrid::kUnknown;
        if (under || reached) cell = geometry::OccupancyGrid::kFree;
      }
    }
  }
}

geometry::OccupancyGrid BuiltMap::seenGrid() const {
  geometry::OccupancyGrid grid = mapper_.grid();
  markGrid(grid, false);
  return grid;
}

geometry::OccupancyGrid BuiltMap::grid(Unknown unknown,
                                       const std::vector<geometry::Point2>& include) const {
  geometry::OccupancyGrid grid = mapper_.grid();
  markGrid(grid, unknown == Unknown::kWall);
  markFootprints(grid);
  if (unknown == Unknown::kFree) {
    // Grown on the mapper's lattice to take in `include` with a metre round each point; every
    // cell not known occupied is floor.
    geometry::Rectangle want = grid.extent();
    for (const geometry::Point2& p : include) {
      want.min_x = std::min(want.min_x, p.x - 1);
      want.min_y = std::min(want.min_y, p.y - 1);
      want.max_x = std::max(want.max_x, p.x + 1);
      want.max_y = std::max(want.max_y, p.y + 1);
    }
    const int left = static_cast<int>(std::ceil((grid.origin.x - want.min_x) / grid.resolution));
    const int below = static_cast<int>(std::ceil((grid.origin.y - want.min_y) / grid.resolution));
    const geometry::Rectangle has = grid.extent();
    const int right = static_cast<int>(std::ceil((want.max_x - has.max_x) / grid.resolution));
    const int above = static_cast<int>(std::ceil((want.max_y - has.max_y) / grid.resolution));
    geometry::OccupancyGrid grown;
    grown.resolution = grid.resolution;
    grown.width = grid.width + left + right;
    grown.height = grid.height + below + above;
    grown.origin = {grid.origin.x - left * grid.resolution,
                    grid.origin.y - below * grid.resolution};
    grown.cells.assign(static_cast<std::size_t>(grown.width) * grown.height,
                       geometry::OccupancyGrid::kFree);
    for (int j = 0; j < grid.height; ++j) {
      for (int i = 0; i < grid.width; ++i) {
        if (grid.at(i, j) == geometry::OccupancyGrid::kOccupied) {
          grown.cells[static_cast<std::size_t>(j + below) * grown.width + i + left] =
              geometry::OccupancyGrid::kOccupied;
        }
      }
    }
    return grown;
  }
  return grid;
}

geometry::OccupancyGrid BuiltMap::fineGrid() const {
  const geometry::OccupancyGrid coarse = grid(Unknown::kWall);
  if (!fine_) return coarse;
  geometry::OccupancyGrid grid = fine_->grid();
  const double cell = grid.resolution;
  for (int j = 0; j < grid.height; ++j) {
    for (int i = 0; i < grid.width; ++i) {
      std::int8_t& value = grid.cells[static_cast<std::size_t>(j) * grid.width + i];
      const std::int64_t gi = std::llround((grid.origin.x - lattice_.x) / cell) + i;
      const std::int64_t gj = std::llround((grid.origin.y - lattice_.y) / cell) + j;
      if (fine_hits_.count(cellKey(gi, gj))) {
        value = geometry::OccupancyGrid::kOccupied;  // a return ended in it
      } else if (!fine_->observed(i, j) || fine_->logOdds(i, j) >= 0) {
        // Not crossed more than hit (not seen at this size, or the bumper's): as its 0.05 m cell.
        const int ci = coarse.column(grid.origin.x + (i + 0.5) * cell);
        const int cj = coarse.row(grid.origin.y + (j + 0.5) * cell);
        value = coarse.inside(ci, cj) ? coarse.at(ci, cj) : geometry::OccupancyGrid::kUnknown;
      } else {
        value = geometry::OccupancyGrid::kFree;
      }
    }
  }
  markFootprints(grid);
  return grid;
}

world::World BuiltMap::world(std::shared_ptr<const geometry::OccupancyGrid> grid,
                             const robot::Pose2D& pose) const {
  world::World world = world::mapWorld(std::move(grid), robot_.radius);
  world.robots.front() = robot_;
  world.robots.front().initial_pose = pose;
  return world;
}

}  // namespace roomba_rrt::exploration
