#include "roomba_rrt/exploration/explore_clean.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "roomba_rrt/coverage/coverage_leaves.h"
#include "roomba_rrt/world_planning/room_problem.h"

namespace roomba_rrt::exploration {
namespace {

const std::string kLooking = "Explore";

/// The map as the robot starts it: 0.05 m cells (gmapping's default), 10 m round the robot,
/// growing as the scans reach farther.
mapping::MapperOptions mapperOptions(const robot::Pose2D& start) {
  mapping::MapperOptions options;
  options.resolution = 0.05;
  options.xmin = start.x - 5;
  options.xmax = start.x + 5;
  options.ymin = start.y - 5;
  options.ymax = start.y + 5;
  return options;
}

}  // namespace

navigation::NavLeafConfig cleaningConfig(const world::World& world,
                                         const behavior::RoombaParams& params,
                                         std::shared_ptr<const coverage::CoveragePlanner> planner) {
  navigation::NavLeafConfig config =
      navigation::inProcessNavConfig(world_planning::roomProblem(world));
  config.params = params;
  config.follower.rate = params.rate;
  config.more_leaves.push_back(coverage::coverageLeaves(std::move(planner)));
  return config;
}

ExploreClean::ExploreClean(const world::RobotSpec& robot, double coverage_cell_size,
                           const behavior::RoombaParams& params, std::uint32_t seed,
                           double pose_latency, ExploreCleanTrees trees)
    : robot_(robot),
      coverage_cell_size_(coverage_cell_size),
      params_(params),
      seed_(seed),
      pose_latency_(pose_latency),
      mapper_(mapperOptions(robot.initial_pose)),
      lattice_(mapper_.origin()),
      trees_(std::move(trees)) {
  frontier_options_.robot_radius = robot_.radius + kGoalMargin;
  frontier_options_.view_distance = kViewDistance;
  footprints_.push_back({robot_.initial_pose.x, robot_.initial_pose.y});
}

ExploreClean::~ExploreClean() = default;

std::string ExploreClean::addScan(const robot::Pose2D& sensor, const mapping::ScanView& scan) {
  std::string why = mapper_.addScan(sensor, scan);
  if (why.empty()) markHits(sensor, scan);
  return why;
}

void ExploreClean::setParams(const behavior::RoombaParams& params) {
  params_ = params;
  if (explore_) explore_->setRoombaParams(params);
  if (clean_) clean_->setRoombaParams(params);
}

robot::Velocity ExploreClean::tick(double time, const robot::BumperState& bumper,
                                   const robot::Pose2D& pose, double pose_stamp) {
  if (bumper.pressed) mapper_.addBump(pose, robot_.radius, bumper);
  if (clean_) {
    clean_->observeTiming(time, pose_stamp);
    return clean_->tick(bumper, pose);
  }
  if (mapper_.scans() == 0) return stop_;  // nothing seen yet (over ROS the first scan may lag)

  const double look_every = none_since_ >= 0 ? 0.2 : kReplanPeriod;
  if ((!explore_ && time - last_look_ >= look_every) || time - last_look_ >= kReplanPeriod) {
    nextGoal(time, pose, false);
  }
  if (clean_) {
    clean_->observeTiming(time, pose_stamp);
    return clean_->tick(bumper, pose);
  }
  if (!explore_) return stop_;
  explore_->observeTiming(time, pose_stamp);
  const robot::Velocity cmd = explore_->tick(bumper, pose);
  const navigation::GoalOutcome outcome = explore_->outcome();
  const bool timed_out = time - goal_since_ > kGoalTimeout;
  if (outcome == navigation::GoalOutcome::kActive && !timed_out) return cmd;
  if (outcome != navigation::GoalOutcome::kSucceeded) given_up_.push_back(goal_);
  explore_.reset();
  nextGoal(time, pose, outcome == navigation::GoalOutcome::kSucceeded);
  return stop_;
}

void ExploreClean::nextGoal(double time, const robot::Pose2D& pose, bool arrived) {
  last_look_ = time;
  footprints_.push_back({pose.x, pose.y});
  // Frontiers on the map as published (free: more likely free than not); the way to them and
  // the plans on the strict one (builtGrid()).
  const geometry::OccupancyGrid seen = builtGrid(false);
  const auto grid = std::make_shared<const geometry::OccupancyGrid>(builtGrid(true));
  const geometry::ClearanceMap known(grid);
  const geometry::Point2 at{pose.x, pose.y};
  // Found once; each give-up below only takes more of their cells away.
  const std::vector<exploration::Frontier> found =
      exploration::findFrontiers(seen, frontier_options_.min_cells);
  std::optional<exploration::FrontierGoal> goal =
      exploration::nearestFrontier(known, seen, at, openFrontiers(found, seen), frontier_options_);
  // Arrived, and the nearest frontier is still in view from here: the robot cannot see it
  // from where it may stand (a shadow under furniture, a gap it cannot reach): given up.
  while (goal && arrived && geometry::distance(goal->goal, at) < kSameGoal) {
    given_up_.push_back(goal->goal);
    goal = exploration::nearestFrontier(known, seen, at, openFrontiers(found, seen),
                                        frontier_options_);
  }
  if (!goal) {
    // Nothing to explore from what the map says now: on the way to a goal, go on; else the
    // cells the last scans showed may not be clearly free yet: stand and look for kConfirmDone.
    if (explore_) return;
    if (none_since_ < 0) none_since_ = time;
    if (time - none_since_ >= kConfirmDone) startCleaning(time, pose);
    return;
  }
  none_since_ = -1;
  if (explore_ && geometry::distance(goal->goal, goal_) < kSameGoal) return;  // on its way there
  const world::World world = builtWorld(grid, pose);
  const planning::Problem problem = world_planning::roomProblem(world);
  navigation::NavLeafConfig config = navigation::inProcessNavConfig(
      problem, navigation::navPlannerOptions(problem), navigation::InProcessPlanner::Mode::kInline);
  config.params = params_;
  config.follower.rate = params_.rate;
  config.pose_latency = pose_latency_;
  explore_ = std::make_unique<navigation::NavBt>(config, seed_, trees_.explore);
  goal_ = goal->goal;
  goal_since_ = time;
  explore_->setGoal({goal_.x, goal_.y, std::atan2(goal_.y - pose.y, goal_.x - pose.x)});
}

void ExploreClean::markHits(const robot::Pose2D& sensor, const mapping::ScanView& scan) {
  const double resolution = mapper_.resolution();
  auto mark = [&](const geometry::Point2& p) {
    hits_.insert(cellKey(static_cast<std::int64_t>(std::floor((p.x - lattice_.x) / resolution)),
                         static_cast<std::int64_t>(std::floor((p.y - lattice_.y) / resolution))));
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
    mark(hit);
    // Two neighbouring returns close together lie on one obstacle: the chord between them
    // lies inside it (on a wall, along it), and so does every cell it crosses, among them the
    // cells the obstacle's edge crosses between the two returns, where no ray ended.
    const double chord = geometry::distance(previous, hit);
    if (previous_hit && chord <= kChord) {
      const int samples = static_cast<int>(std::ceil(chord / (0.2 * resolution)));
      for (int s = 1; s < samples; ++s) {
        const double t = static_cast<double>(s) / samples;
        mark({previous.x + t * (hit.x - previous.x), previous.y + t * (hit.y - previous.y)});
      }
    }
    previous = hit;
    previous_hit = true;
  }
}

geometry::OccupancyGrid ExploreClean::builtGrid(bool strict) const {
  geometry::OccupancyGrid grid = mapper_.grid();
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
      // A ray ended in it: an obstacle's edge crosses it, however many rays passed its free part.
      const std::int64_t gi = std::llround((grid.origin.x - lattice_.x) / grid.resolution) + i;
      const std::int64_t gj = std::llround((grid.origin.y - lattice_.y) / grid.resolution) + j;
      if (hits_.count(cellKey(gi, gj))) cell = geometry::OccupancyGrid::kOccupied;
    }
  }
  if (!strict) return grid;
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
  return grid;
}

std::vector<exploration::Frontier> ExploreClean::openFrontiers(
    std::vector<exploration::Frontier> frontiers, const geometry::OccupancyGrid& grid) const {
  std::vector<exploration::Frontier> open;
  for (exploration::Frontier& frontier : frontiers) {
    auto near_given_up = [&](int cell) {
      const geometry::Point2 c{grid.origin.x + (cell % grid.width + 0.5) * grid.resolution,
                               grid.origin.y + (cell / grid.width + 0.5) * grid.resolution};
      return std::any_of(given_up_.begin(), given_up_.end(), [&](const geometry::Point2& g) {
        return geometry::distance(c, g) <= frontier_options_.view_distance + kGiveUpMargin;
      });
    };
    frontier.cells.erase(
        std::remove_if(frontier.cells.begin(), frontier.cells.end(), near_given_up),
        frontier.cells.end());
    if (static_cast<int>(frontier.cells.size()) >= frontier_options_.min_cells) {
      open.push_back(std::move(frontier));
    }
  }
  return open;
}

world::World ExploreClean::builtWorld(std::shared_ptr<const geometry::OccupancyGrid> grid,
                                      const robot::Pose2D& pose) const {
  world::World world = world::mapWorld(std::move(grid), robot_.radius);
  world.robots.front() = robot_;
  world.robots.front().initial_pose = pose;
  world.coverage_cell_size = coverage_cell_size_;
  world.coverage_cell_size_given = true;
  return world;
}

void ExploreClean::startCleaning(double time, const robot::Pose2D& pose) {
  explored_at_ = time;
  explore_.reset();
  footprints_.push_back({pose.x, pose.y});
  const auto grid = std::make_shared<const geometry::OccupancyGrid>(builtGrid(true));
  const world::World world = builtWorld(grid, pose);
  navigation::NavLeafConfig config = cleaningConfig(
      world, params_,
      std::make_shared<const coverage::CoveragePlanner>(world, coverage::cleaningOptions(world)));
  config.pose_latency = pose_latency_;
  clean_ = std::make_unique<navigation::NavBt>(config, seed_, trees_.clean);
}

const std::string& ExploreClean::stateName() const {
  if (clean_) return clean_->stateName();
  if (explore_) return explore_->stateName();
  return kLooking;
}

behavior::RoombaState ExploreClean::state() const {
  if (clean_) return clean_->state();
  if (explore_) return explore_->state();
  return behavior::RoombaState::kRotate;
}

}  // namespace roomba_rrt::exploration
