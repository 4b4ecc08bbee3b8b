#include "roomba_rrt/exploration/explore_clean.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "roomba_rrt/coverage/coverage_leaves.h"
#include "roomba_rrt/world_planning/room_problem.h"

namespace roomba_rrt::exploration {
namespace {

const std::string kLooking = "Explore";

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
      map_(robot, nullptr, kFineSplit),
      trees_(std::move(trees)) {
  frontier_options_.robot_radius = robot_.radius + kGoalMargin;
  frontier_options_.view_distance = kViewDistance;
}

ExploreClean::~ExploreClean() = default;

std::string ExploreClean::addScan(const robot::Pose2D& sensor, const mapping::ScanView& scan) {
  return map_.addScan(sensor, scan);
}

void ExploreClean::setParams(const behavior::RoombaParams& params) {
  params_ = params;
  if (explore_) explore_->setRoombaParams(params);
  if (clean_) clean_->setRoombaParams(params);
}

robot::Velocity ExploreClean::tick(double time, const robot::BumperState& bumper,
                                   const robot::Pose2D& pose, double pose_stamp) {
  if (bumper.pressed) map_.addBump(pose, bumper);
  if (swept_at_.empty() || geometry::distance(swept_at_.back(), {pose.x, pose.y}) >= kSweptStep) {
    swept_at_.push_back({pose.x, pose.y});
  }
  if (clean_ && (clean_->idle() || cleaningTouchedUp()) && rounds_ < kTouchUpRounds &&
      !trees_.touch_up.empty()) {
    startTouchUp(pose);
  }
  if (clean_) {
    clean_->observeTiming(time, pose_stamp);
    const robot::Velocity cmd = clean_->tick(bumper, pose);
    // The round is planned on the next tick (a second on a large map): the robot waits for it
    // standing, as it does after a tree that is done, not driving on towards the next pass.
    return cleaningTouchedUp() ? stop_ : cmd;
  }
  if (map_.mapper().scans() == 0)
    return stop_;  // nothing seen yet (over ROS the first scan may lag)

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

bool ExploreClean::cleaningTouchedUp() const {
  if (rounds_ > 0 || !clean_) return false;
  // The tree plans its next pass on the tick its last one is driven to the end: one more pass
  // planned than kCleanTouchUps means those are driven.
  const coverage::CoverageProgress* progress = coverage::findProgress(clean_->tree().blackboard());
  return progress && progress->touch_ups > kCleanTouchUps;
}

void ExploreClean::nextGoal(double time, const robot::Pose2D& pose, bool arrived) {
  last_look_ = time;
  map_.stoodAt({pose.x, pose.y});
  // Frontiers on the map as published (free: more likely free than not); the way to them and
  // the plans on the strict one (unknown cells as walls).
  const geometry::OccupancyGrid seen = map_.seenGrid();
  const auto grid =
      std::make_shared<const geometry::OccupancyGrid>(map_.grid(BuiltMap::Unknown::kWall));
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
  // At the cleaning's transit speed, and any heading at the frontier: the lidar sees all round.
  config.follower.max_linear_speed = std::min(kExploreSpeed, robot_.max_linear_speed);
  config.follower.yaw_tolerance = navigation::FollowerLimits::kMaxYawTolerance;
  config.pose_latency = pose_latency_;
  explore_ = std::make_unique<navigation::NavBt>(config, seed_, trees_.explore);
  goal_ = goal->goal;
  goal_since_ = time;
  explore_->setGoal({goal_.x, goal_.y, std::atan2(goal_.y - pose.y, goal_.x - pose.x)});
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
  world::World world = map_.world(std::move(grid), pose);
  world.coverage_cell_size = coverage_cell_size_;
  world.coverage_cell_size_given = true;
  return world;
}

navigation::NavLeafConfig ExploreClean::cleaningOnMap(
    const robot::Pose2D& pose, double cell_size,
    std::shared_ptr<const coverage::CoveragePlanner>& planner) {
  map_.stoodAt({pose.x, pose.y});
  const auto grid = std::make_shared<const geometry::OccupancyGrid>(map_.fineGrid());
  world::World world = builtWorld(grid, pose);
  world.coverage_cell_size = cell_size;
  planner =
      std::make_shared<const coverage::CoveragePlanner>(world, coverage::cleaningOptions(world));
  navigation::NavLeafConfig config = cleaningConfig(world, params_, planner);
  config.pose_latency = pose_latency_;
  return config;
}

void ExploreClean::startCleaning(double time, const robot::Pose2D& pose) {
  explored_at_ = time;
  explore_.reset();
  std::shared_ptr<const coverage::CoveragePlanner> planner;
  clean_ = std::make_unique<navigation::NavBt>(cleaningOnMap(pose, coverage_cell_size_, planner),
                                               seed_, trees_.clean);
}

void ExploreClean::startTouchUp(const robot::Pose2D& pose) {
  ++rounds_;
  std::shared_ptr<const coverage::CoveragePlanner> planner;
  const navigation::NavLeafConfig config =
      cleaningOnMap(pose, coverage_cell_size_ / kTouchUpSplit, planner);
  // Nothing planned yet, and the floor swept so far on the new map's lattice.
  coverage::CoverageProgress progress;
  for (const geometry::Point2& p : swept_at_) planner->markSwept(progress.swept, p);
  clean_ = std::make_unique<navigation::NavBt>(config, seed_, trees_.touch_up);
  clean_->tree().blackboard().set("coverage", progress);
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
