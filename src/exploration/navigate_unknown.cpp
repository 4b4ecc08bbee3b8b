#include "roomba_rrt/exploration/navigate_unknown.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "roomba_rrt/planning/free_point_near.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/world_planning/room_problem.h"

namespace roomba_rrt::exploration {
namespace {

const std::string kNoGoal = "Idle";

/// The part of `path` still ahead of a robot at `at`: `at`, then every point after the segment
/// nearest to it.
navigation::Path ahead(const navigation::Path& path, const geometry::Point2& at) {
  const std::size_t nearest = navigation::nearestSegment(path, at);
  navigation::Path rest{{at.x, at.y}};
  rest.insert(rest.end(),
              path.begin() + static_cast<std::ptrdiff_t>(std::min(nearest + 1, path.size())),
              path.end());
  return rest;
}

}  // namespace

NavigateUnknown::NavigateUnknown(const world::RobotSpec& robot,
                                 const behavior::RoombaParams& params, std::uint32_t seed,
                                 double pose_latency, std::string tree_file, const KnownMap* known)
    : robot_(robot),
      params_(params),
      seed_(seed),
      pose_latency_(pose_latency),
      tree_file_(std::move(tree_file)),
      map_(robot, known ? checkKnownMap(*known, robot) : nullptr),
      last_footprint_{robot.initial_pose.x, robot.initial_pose.y} {
  follower_.rate = params_.rate;
}

NavigateUnknown::~NavigateUnknown() = default;

std::string NavigateUnknown::addScan(const robot::Pose2D& sensor, const mapping::ScanView& scan) {
  return map_.addScan(sensor, scan);
}

void NavigateUnknown::setGoal(const robot::Pose2D& goal) {
  if (!std::isfinite(goal.x)) throw util::InvalidInput("goal.x", "is not finite");
  if (!std::isfinite(goal.y)) throw util::InvalidInput("goal.y", "is not finite");
  if (!std::isfinite(goal.theta)) throw util::InvalidInput("goal.theta", "is not finite");
  const mapping::OccupancyMapper& mapper = map_.mapper();
  const geometry::Point2 low = mapper.origin();
  const geometry::Rectangle known{low.x, low.y, low.x + mapper.width() * mapper.resolution(),
                                  low.y + mapper.height() * mapper.resolution()};
  const double dx = std::max({known.min_x - goal.x, 0.0, goal.x - known.max_x});
  const double dy = std::max({known.min_y - goal.y, 0.0, goal.y - known.max_y});
  if (std::hypot(dx, dy) > kMaxGoalDistance) {
    throw util::InvalidInput("goal", util::show(std::hypot(dx, dy)) +
                                         " m beyond the map the robot has built (at most " +
                                         util::show(kMaxGoalDistance) + " m)");
  }
  goal_ = goal;
  nav_.reset();  // the next tick plans on the map as it is then
  outcome_ = navigation::GoalOutcome::kActive;
  message_.clear();
  plans_ = 0;
  retries_ = 0;
}

void NavigateUnknown::cancelGoal() {
  nav_.reset();
  outcome_ = navigation::GoalOutcome::kNone;
}

void NavigateUnknown::setFollowerParams(const navigation::FollowerParams& params) {
  navigation::FollowerParams next = params;
  next.rate = params_.rate;
  navigation::validate(next);
  if (nav_) nav_->setFollowerParams(next);
  follower_ = next;
}

void NavigateUnknown::end(navigation::GoalOutcome outcome, std::string message) {
  outcome_ = outcome;
  message_ = std::move(message);
  nav_.reset();
}

robot::Velocity NavigateUnknown::tick(double time, const robot::BumperState& bumper,
                                      const robot::Pose2D& pose, double pose_stamp) {
  if (bumper.pressed) map_.addBump(pose, bumper);
  if (outcome_ != navigation::GoalOutcome::kActive) return stop_;
  if (map_.mapper().scans() == 0) return stop_;  // nothing seen yet (over ROS it may lag)
  if (!nav_ || time - last_look_ >= kLookPeriod) look(time, pose);
  nav_->observeTiming(time, pose_stamp);
  const robot::Velocity cmd = nav_->tick(bumper, pose);
  switch (nav_->outcome()) {
    case navigation::GoalOutcome::kSucceeded:
      end(navigation::GoalOutcome::kSucceeded, "");
      return stop_;
    case navigation::GoalOutcome::kAborted:
    case navigation::GoalOutcome::kNone:
      // The tree gave up on the map it was given; the map has grown since: a new tree plans on
      // it, kRetries times before the goal is given up.
      if (retries_ < kRetries) {
        ++retries_;
        nav_.reset();
        return stop_;
      }
      end(navigation::GoalOutcome::kAborted, nav_->message());
      return stop_;
    case navigation::GoalOutcome::kActive:
      break;
  }
  return cmd;
}

void NavigateUnknown::look(double time, const robot::Pose2D& pose) {
  last_look_ = time;
  const geometry::Point2 at{pose.x, pose.y};
  if (geometry::distance(at, last_footprint_) >= kFootprintSpacing) {
    map_.stoodAt(at);
    last_footprint_ = at;
  }
  if (nav_ && !nav_->path()) return;  // its first plan is still to come
  const auto grid = std::make_shared<const geometry::OccupancyGrid>(
      map_.grid(BuiltMap::Unknown::kFree, {at, {goal_.x, goal_.y}}));
  planning::Problem problem = world_planning::roomProblem(map_.world(grid, pose));
  problem.clearance = navigation::kDefaultClearance;  // as roomba_bt's ~clearance
  if (nav_ && nav_->path() &&
      navigation::PathChecker(problem).isPathFree(ahead(*nav_->path(), at), 0)) {
    return;  // the way ahead is still free in what the robot knows now
  }
  navigation::NavLeafConfig config = navigation::inProcessNavConfig(
      problem, navigation::navPlannerOptions(problem), navigation::InProcessPlanner::Mode::kInline);
  config.params = params_;
  config.follower = follower_;
  config.pose_latency = pose_latency_;
  nav_ = std::make_unique<navigation::NavBt>(config, seed_ + static_cast<std::uint32_t>(plans_),
                                             tree_file_);
  // A goal the map puts too close to an obstacle (its cells are squares round what the rays hit,
  // up to a cell's diagonal wider than the obstacle) is driven to the nearest free point within
  // kGoalShift, as make_plan's tolerance moves it.
  const std::optional<planning::Point2> free =
      planning::freePointNear(problem, {goal_.x, goal_.y}, kGoalShift);
  nav_->setGoal(free ? robot::Pose2D{free->x, free->y, goal_.theta} : goal_);
  ++plans_;
}

const std::string& NavigateUnknown::stateName() const { return nav_ ? nav_->stateName() : kNoGoal; }

}  // namespace roomba_rrt::exploration
