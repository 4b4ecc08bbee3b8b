#include "roomba_rrt/exploration/bump_clean.h"

#include <algorithm>
#include <cmath>

#include "roomba_rrt/robot/unicycle.h"

namespace roomba_rrt::exploration {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// m beyond an IR return where it counts: a hair inside what it hit.
constexpr double kInside = 1e-3;
/// m: a drive ends this close to its end, or to a point found ahead.
constexpr double kEndGap = OnlineBoustrophedon::kStopShort;
/// rad: a turn before a drive ends this close to the move's heading.
constexpr double kHeadingTolerance = 0.02;
constexpr double kTurnGain = 8.0;     ///< 1/s: turning in place (as the cleaning tree)
constexpr double kTurnAccel = 16.0;   ///< rad/s² (as the cleaning tree)
constexpr double kHeadingGain = 4.0;  ///< 1/s: holding a drive's heading
constexpr double kLineGain = 5.0;     ///< rad/m: steering back onto a drive's line
/// A row ends when the disc's next kRowLookahead m would sweep less new floor than kRowMinGain
/// (m²): it has run into floor it swept before.
constexpr double kRowLookahead = 0.15;
constexpr double kRowMinGain = 0.004;
/// s a back-off may take at most (pressed against something behind it too).
constexpr double kBackUpTimeout = 1.0;

const std::string kNames[] = {"Transit", "Turn", "Row", "Shift", "BackUp", "Done"};

navigation::FollowerParams followerParams(const behavior::RoombaParams& params,
                                          const BumpCleanOptions& options) {
  navigation::FollowerParams p;
  p.max_linear_speed = options.transit_speed;
  p.max_angular_speed = options.turn_speed;
  p.max_linear_accel = options.accel;
  p.max_angular_accel = kTurnAccel;
  p.heading_gain = kTurnGain;
  p.xy_tolerance = 0.01;
  // Turned in place until within 0.15 rad of the way to go: the transits start beside walls the
  // robot has not seen all of, and an arc started 0.45 rad off (the follower's default) swings
  // the disc 2 cm towards them.
  p.rotate_threshold = 0.3;
  p.yaw_tolerance = 0.05;
  p.rate = params.rate;
  return p;
}

}  // namespace

bool cleansByTouch(const world::RobotSpec& robot) {
  return std::none_of(robot.sensors.begin(), robot.sensors.end(),
                      [](const sensors::RangeSensorSpec& s) { return s.range_max >= kLongRange; });
}

BumpClean::BumpClean(const world::RobotSpec& robot, const behavior::RoombaParams& params,
                     const BumpCleanOptions& options)
    : robot_(robot),
      params_(params),
      options_(options),
      map_({robot.initial_pose.x, robot.initial_pose.y}, robot.radius, options.clearance),
      planner_({robot.initial_pose.x, robot.initial_pose.y}, robot.initial_pose.theta,
               options.plan),
      follower_(followerParams(params, options)) {}

std::string BumpClean::addScan(const robot::Pose2D& sensor, const mapping::ScanView& scan) {
  if (!std::isfinite(sensor.x) || !std::isfinite(sensor.y) || !std::isfinite(sensor.theta)) {
    return "sensor pose: must be finite";
  }
  std::string why = mapping::checkScan(scan);
  if (!why.empty()) return why;
  const double first = mapping::firstRayAngle(sensor.theta, scan);
  for (std::size_t k = 0; k < scan.count; ++k) {
    const double range = scan.ranges[k];
    if (!(range >= scan.range_min && range <= scan.range_max)) continue;  // none, or NaN
    const double a = first + static_cast<double>(k) * scan.angle_increment;
    const double r = range + kInside;
    map_.markObstacle({sensor.x + r * std::cos(a), sensor.y + r * std::sin(a)});
  }
  return "";
}

void BumpClean::markBump(const robot::Pose2D& pose, const robot::BumperState& bumper) {
  // Where the switches say, on the side the robot was moving to (the mapper's convention:
  // both ahead, one 45° to its side).
  double a = pose.theta + (bumper.left && bumper.right ? 0.0 : bumper.left ? kPi / 4 : -kPi / 4);
  if (last_.v < 0) a += kPi;  // backing into it
  const double r = robot_.radius + 0.005;
  map_.markObstacle({pose.x + r * std::cos(a), pose.y + r * std::sin(a)});
}

robot::Velocity BumpClean::tick(double time, const robot::BumperState& bumper,
                                const robot::Pose2D& pose) {
  const geometry::Point2 at{pose.x, pose.y};
  map_.sweep(at);
  const bool bumped = bumper.pressed && !was_pressed_;
  was_pressed_ = bumper.pressed;
  if (bumper.pressed) markBump(pose, bumper);
  if (!started_) {
    started_ = true;
    plan(time, pose);
  }
  if (bumped && phase_ != Phase::kDone) {
    if (phase_ == Phase::kBackUp) {
      plan(time, pose);  // backed into something as well: choose again from here
    } else {
      phase_ = Phase::kBackUp;
      backup_from_ = at;
      move_since_ = time;
    }
  }
  robot::Velocity cmd;
  // A phase that ends hands the tick to the next (at most a drive's end, a plan, a turn's end).
  for (int hand_over = 0; hand_over < 4; ++hand_over) {
    const Phase before = phase_;
    cmd = {};
    switch (phase_) {
      case Phase::kDone:
        break;
      case Phase::kBackUp:
        if (geometry::distance(at, backup_from_) >= options_.backup ||
            time - move_since_ > kBackUpTimeout) {
          plan(time, pose);
        } else {
          cmd = {-options_.backup_speed, 0};
        }
        break;
      case Phase::kTransit: {
        const navigation::FollowStatus status = follower_.step(pose, cmd);
        if (status == navigation::FollowStatus::kArrived) {
          phase_ = Phase::kTurn;
        } else if (status != navigation::FollowStatus::kFollowing ||
                   time - move_since_ > options_.move_timeout) {
          plan(time, pose);
        }
        break;
      }
      case Phase::kTurn:
        cmd = turn(time, pose);
        break;
      case Phase::kDrive:
        cmd = drive(time, pose);
        break;
    }
    if (phase_ == before) break;
  }
  last_ = cmd;
  return cmd;
}

void BumpClean::plan(double time, const robot::Pose2D& pose) {
  if (move_ && map_.sweptCells() == swept_before_) planner_.sweptNothing(map_, *move_);
  swept_before_ = map_.sweptCells();
  move_ = planner_.next(map_, {pose.x, pose.y});
  move_since_ = time;
  if (!move_) {
    phase_ = Phase::kDone;
    done_at_ = time;
    return;
  }
  ++moves_;
  if (move_->transit.empty()) {
    phase_ = Phase::kTurn;
    return;
  }
  path_.assign(move_->transit.begin(), move_->transit.end());
  follower_.start(path_, {move_->start.x, move_->start.y, yaw(move_->heading)}, last_);
  phase_ = Phase::kTransit;
}

double BumpClean::ramp(double v) const {
  return std::min(v, last_.v + options_.accel / params_.rate);
}

robot::Velocity BumpClean::turn(double time, const robot::Pose2D& pose) {
  const double error = robot::wrapAngle(yaw(move_->heading) - pose.theta);
  if (std::abs(error) < kHeadingTolerance) {
    phase_ = Phase::kDrive;
    return {};
  }
  if (time - move_since_ > options_.move_timeout) {
    plan(time, pose);
    return {};
  }
  // As fast as the robot turns, braking to stop on the heading.
  const double most = std::min({options_.turn_speed, kTurnGain * std::abs(error),
                                std::sqrt(2 * kTurnAccel * std::abs(error)),
                                std::abs(last_.w) + kTurnAccel / params_.rate});
  return {0, std::copysign(most, error)};
}

robot::Velocity BumpClean::drive(double time, const robot::Pose2D& pose) {
  const Move& move = *move_;
  const geometry::Point2 u = unit(move.heading);
  const geometry::Point2 at{pose.x, pose.y};
  const double along = (at.x - move.start.x) * u.x + (at.y - move.start.y) * u.y;
  const double across = u.x * (at.y - move.start.y) - u.y * (at.x - move.start.x);
  const double free = map_.freeLength(at, u, 1.0);
  double left = free - kEndGap;
  bool end = left <= 0 || time - move_since_ > options_.move_timeout;
  if (move.kind == Move::Kind::kShift) {
    // On past the row line to what the robot found ahead when that is less than kSnapToWall
    // beyond it: the row after it sweeps the strip along it (else a strip is left that only
    // shifts of a few centimetres, one at a time, could sweep).
    const double to_line = move.length - along;
    if (free - to_line > OnlineBoustrophedon::kSnapToWall) left = to_line - kEndGap;
    end = end || left <= 0;
  } else {
    const geometry::Point2 on_line{move.start.x + along * u.x, move.start.y + along * u.y};
    end = end ||
          OnlineBoustrophedon::newFloor(map_, on_line, move.heading, kRowLookahead) < kRowMinGain;
  }
  if (end) {
    plan(time, pose);
    return {};
  }
  const double v = ramp(std::min(params_.forward_speed, std::sqrt(2 * options_.accel * left)));
  const double heading = yaw(move.heading) - std::atan(kLineGain * across);
  const double w = std::clamp(kHeadingGain * robot::wrapAngle(heading - pose.theta),
                              -options_.turn_speed, options_.turn_speed);
  return {v, w};
}

const std::string& BumpClean::stateName() const {
  switch (phase_) {
    case Phase::kTransit:
      return kNames[0];
    case Phase::kTurn:
      return kNames[1];
    case Phase::kDrive:
      return kNames[move_ && move_->kind == Move::Kind::kShift ? 3 : 2];
    case Phase::kBackUp:
      return kNames[4];
    case Phase::kDone:
      return kNames[5];
  }
  return kNames[5];
}

behavior::RoombaState BumpClean::state() const {
  switch (phase_) {
    case Phase::kDrive:
      return behavior::RoombaState::kMoveForward;
    case Phase::kTransit:
      return behavior::RoombaState::kMoveInSpiral;
    case Phase::kBackUp:
      return behavior::RoombaState::kGoBack;
    default:
      return behavior::RoombaState::kRotate;
  }
}

}  // namespace roomba_rrt::exploration
