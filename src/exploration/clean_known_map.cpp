#include "roomba_rrt/exploration/clean_known_map.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "roomba_rrt/coverage/coverage_leaves.h"
#include "roomba_rrt/exploration/explore_clean.h"
#include "roomba_rrt/navigation/path_checker.h"

namespace roomba_rrt::exploration {
namespace {

const std::string kWaiting = "Idle";

/// `swept` (one flag per lattice point of `from`) on the lattice of `to`: each point of `to`
/// takes the flag of the point of `from` nearest it, when one lies within half a step (the two
/// lattices are the same but for where the map's known part begins).
std::vector<std::uint8_t> sweptOn(const coverage::FreeSpace& to, const coverage::FreeSpace& from,
                                  const std::vector<std::uint8_t>& swept) {
  std::vector<std::uint8_t> out(to.size(), 0);
  if (swept.empty()) return out;
  const double h = from.resolution();
  const geometry::Point2 o = from.point(0, 0);
  for (int k = 0; k < to.size(); ++k) {
    const geometry::Point2 p = to.point(k);
    const int i = static_cast<int>(std::lround((p.x - o.x) / h));
    const int j = static_cast<int>(std::lround((p.y - o.y) / h));
    if (!from.inside(i, j)) continue;
    const int n = from.index(i, j);
    if (static_cast<std::size_t>(n) < swept.size() &&
        geometry::distance(from.point(n), p) <= h / 2) {
      out[k] = swept[n];
    }
  }
  return out;
}

}  // namespace

CleanKnownMap::CleanKnownMap(const world::RobotSpec& robot, const KnownMap& known,
                             double coverage_cell_size, const behavior::RoombaParams& params,
                             std::uint32_t seed, double pose_latency, std::string tree_file)
    : robot_(robot),
      coverage_cell_size_(coverage_cell_size),
      params_(params),
      seed_(seed),
      pose_latency_(pose_latency),
      tree_file_(std::move(tree_file)),
      map_(robot, checkKnownMap(known, robot)),
      last_footprint_{robot.initial_pose.x, robot.initial_pose.y} {}

CleanKnownMap::~CleanKnownMap() = default;

std::string CleanKnownMap::addScan(const robot::Pose2D& sensor, const mapping::ScanView& scan) {
  return map_.addScan(sensor, scan);
}

void CleanKnownMap::setParams(const behavior::RoombaParams& params) {
  params_ = params;
  if (clean_) clean_->setRoombaParams(params);
}

robot::Velocity CleanKnownMap::tick(double time, const robot::BumperState& bumper,
                                    const robot::Pose2D& pose, double pose_stamp) {
  if (bumper.pressed) map_.addBump(pose, bumper);
  if (map_.mapper().scans() == 0) return stop_;  // nothing seen yet (over ROS the first may lag)
  const geometry::Point2 at{pose.x, pose.y};
  if (geometry::distance(at, last_footprint_) >= kFootprintSpacing) {
    map_.stoodAt(at);
    last_footprint_ = at;
  }
  // After each scan; not while the bumper is pressed or the tree backs off: it resumes first,
  // then is looked at.
  const bool backing_up = clean_ && clean_->state() == behavior::RoombaState::kGoBack;
  if (!clean_ || (map_.mapper().scans() != checked_scans_ && !bumper.pressed && !backing_up &&
                  !clean_->idle())) {
    checked_scans_ = map_.mapper().scans();
    auto grid =
        std::make_shared<const geometry::OccupancyGrid>(map_.grid(BuiltMap::Unknown::kWall));
    if (!clean_ || restChanged(*grid, pose)) plan(std::move(grid), pose);
  }
  clean_->observeTiming(time, pose_stamp);
  return clean_->tick(bumper, pose);
}

bool CleanKnownMap::restChanged(const geometry::OccupancyGrid& grid, const robot::Pose2D& pose) {
  const coverage::CoverageProgress* progress = coverage::findProgress(clean_->tree().blackboard());
  if (!progress || !planned_) return false;
  coverage::Polyline rest = coverage::remainingPath(*progress);
  if (rest.size() < 2) return false;
  const geometry::Point2 at{pose.x, pose.y};
  // From where the robot is along the current leg on.
  const std::size_t from = navigation::nearestSegment(rest, at);
  rest.erase(rest.begin(), rest.begin() + static_cast<std::ptrdiff_t>(from));
  rest.front() = geometry::closestPoint({rest[0], rest[1]}, at);
  const geometry::OccupancyGrid& before = *planned_;
  // Whether a cell of `grid` whose square comes within `reach` of p is blocked now and was
  // floor in the map the tree plans and guards on.
  auto changedNear = [&](const geometry::Point2& p, double reach) {
    const int n = static_cast<int>(std::ceil(reach / grid.resolution));
    const int ci = grid.column(p.x), cj = grid.row(p.y);
    for (int j = cj - n; j <= cj + n; ++j) {
      for (int i = ci - n; i <= ci + n; ++i) {
        if (!grid.inside(i, j) || grid.at(i, j) == geometry::OccupancyGrid::kFree) continue;
        const geometry::Rectangle s = grid.square(i, j);
        if (geometry::squaredDistance(s, p) >= reach * reach) continue;
        const geometry::Point2 c{(s.min_x + s.max_x) / 2, (s.min_y + s.max_y) / 2};
        const int bi = before.column(c.x), bj = before.row(c.y);
        if (before.inside(bi, bj) && before.at(bi, bj) == geometry::OccupancyGrid::kFree) {
          return true;
        }
      }
    }
    return false;
  };
  // A robot whose own disc meets what changed (it bumped, or saw it late beside it) is not
  // stopped by where it stands: the rest is looked at from kAroundRobot on.
  const double reach = robot_.radius + kGuardMargin;
  const double skip = changedNear(at, robot_.radius) ? kAroundRobot : 0.0;
  double ahead = 0;  // m of the rest looked at so far
  for (std::size_t k = 0; k + 1 < rest.size() && ahead < kCheckAhead; ++k) {
    const double length = geometry::distance(rest[k], rest[k + 1]);
    ahead += length;
    const int samples = std::max(1, static_cast<int>(std::ceil(length / kCheckStep)));
    for (int s = 0; s <= samples; ++s) {
      const double t = static_cast<double>(s) / samples;
      const geometry::Point2 p{rest[k].x + t * (rest[k + 1].x - rest[k].x),
                               rest[k].y + t * (rest[k + 1].y - rest[k].y)};
      if (geometry::distance(p, at) < skip) continue;
      if (changedNear(p, reach)) return true;
    }
  }
  return false;
}

void CleanKnownMap::plan(std::shared_ptr<const geometry::OccupancyGrid> grid,
                         const robot::Pose2D& pose) {
  map_.stoodAt({pose.x, pose.y});
  planned_ = grid;
  world::World world = map_.world(std::move(grid), pose);
  world.coverage_cell_size = coverage_cell_size_;
  world.coverage_cell_size_given = true;
  auto planner =
      std::make_shared<const coverage::CoveragePlanner>(world, coverage::cleaningOptions(world));
  navigation::NavLeafConfig config = cleaningConfig(world, params_, planner);
  const coverage::CoverageProgress* progress =
      clean_ ? coverage::findProgress(clean_->tree().blackboard()) : nullptr;
  if (progress) {
    // The rest of the plan made free on the new map, in the same order; the floor swept so far
    // on the new planner's lattice, for the touch-up.
    coverage::CoverageProgress next = *progress;
    next.plan = planner->repair(progress->plan, progress->leg, {pose.x, pose.y});
    next.leg = 0;
    next.tries = 0;
    next.swept = sweptOn(planner->freeSpace(), planner_->freeSpace(), progress->swept);
    config.more_leaves.back() = coverage::coverageLeaves(planner, std::move(next));
  }
  config.pose_latency = pose_latency_;
  clean_ = std::make_unique<navigation::NavBt>(config, seed_, tree_file_);
  planner_ = std::move(planner);
  ++plans_;
}

const std::string& CleanKnownMap::stateName() const {
  return clean_ ? clean_->stateName() : kWaiting;
}

behavior::RoombaState CleanKnownMap::state() const {
  return clean_ ? clean_->state() : behavior::RoombaState::kRotate;
}

}  // namespace roomba_rrt::exploration
