#include "roomba_rrt/navigation/path_follower.h"

#include <algorithm>
#include <cmath>
#include "roomba_rrt/robot/unicycle.h"
#include "roomba_rrt/util/require.h"

namespace roomba_rrt::navigation {
namespace {

using planning::Point2;

using util::requirePositive;

double sign(double x) { return x < 0 ? -1.0 : 1.0; }

/// Speed for turning through `error` radians and stopping on it: min(limit, gain·|e|,
/// √(2·accel·|e|)), with the sign of the error.
double turnRate(double error, double limit, double gain, double accel) {
  const double magnitude = std::fabs(error);
  return sign(error) * std::min({limit, gain * magnitude, std::sqrt(2.0 * accel * magnitude)});
}

}  // namespace

void validate(const FollowerParams& p) {
  requirePositive("max_linear_speed", p.max_linear_speed);
  requirePositive("max_angular_speed", p.max_angular_speed);
  requirePositive("max_linear_accel", p.max_linear_accel);
  requirePositive("max_angular_accel", p.max_angular_accel);
  requirePositive("lookahead", p.lookahead);
  requirePositive("xy_tolerance", p.xy_tolerance);
  requirePositive("yaw_tolerance", p.yaw_tolerance);
  requirePositive("max_deviation", p.max_deviation);
  requirePositive("rotate_threshold", p.rotate_threshold);
  requirePositive("heading_gain", p.heading_gain);
  requirePositive("rate", p.rate);
  const auto requireAtMost = [](const char* field, double value, double max) {
    if (value > max) {
      throw util::InvalidInput(field,
                               "must be at most " + util::show(max) + ", got " + util::show(value));
    }
  };
  requireAtMost("max_linear_speed", p.max_linear_speed, FollowerLimits::kMaxSpeed);
  requireAtMost("max_angular_speed", p.max_angular_speed, FollowerLimits::kMaxSpeed);
  requireAtMost("xy_tolerance", p.xy_tolerance, FollowerLimits::kMaxXyTolerance);
  requireAtMost("yaw_tolerance", p.yaw_tolerance, FollowerLimits::kMaxYawTolerance);
  if (p.max_deviation <= p.xy_tolerance) {
    throw util::InvalidInput("max_deviation", "must be > xy_tolerance (" +
                                                  util::show(p.xy_tolerance) + "), got " +
                                                  util::show(p.max_deviation));
  }
}

const char* toString(FollowStatus status) {
  switch (status) {
    case FollowStatus::kFollowing:
      return "following";
    case FollowStatus::kArrived:
      return "arrived";
    case FollowStatus::kStrayed:
      return "strayed";
    case FollowStatus::kNoPath:
      return "no path";
    case FollowStatus::kBlocked:
      return "blocked";
  }
  return "?";
}

PathFollower::PathFollower(const FollowerParams& params) : params_(params) { validate(params_); }

void PathFollower::setParams(const FollowerParams& params) {
  validate(params);
  params_ = params;
}

void PathFollower::start(const Path& path, const robot::Pose2D& goal,
                         const robot::Velocity& current) {
  path_ = &path;
  goal_ = goal;
  total_length_ = planning::pathLength(path);
  segment_ = 0;
  segment_start_s_ = 0;
  progress_s_ = 0;
  deviation_ = 0;
  at_goal_ = false;
  turning_in_place_ = false;
  last_ = current;
}

double PathFollower::project(const Point2& p) {
  const Path& path = *path_;
  if (path.size() == 1) return planning::distance(p, path[0]);
  const double window = progress_s_ + std::max(4.0 * params_.lookahead, 1.0);
  double best = std::numeric_limits<double>::infinity();
  double s = segment_start_s_;
  for (std::size_t i = segment_; i + 1 < path.size() && s <= window; ++i) {
    const Point2& a = path[i];
    const Point2& b = path[i + 1];
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const double length_sq = dx * dx + dy * dy;
    const double length = std::sqrt(length_sq);
    double t = 0;
    if (length_sq > 0) t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length_sq, 0.0, 1.0);
    const double d = std::hypot(a.x + t * dx - p.x, a.y + t * dy - p.y);
    if (d < best) {
      best = d;
      if (i != segment_) {
        segment_ = i;
        segment_start_s_ = s;
      }
      progress_s_ = std::max(progress_s_, s + t * length);
    }
    s += length;
  }
  return best;
}

Point2 PathFollower::pointAt(double s) const {
  const Path& path = *path_;
  double start = segment_start_s_;
  for (std::size_t i = segment_; i + 1 < path.size(); ++i) {
    const double length = planning::distance(path[i], path[i + 1]);
    if (start + length >= s && length > 0) {
      const double t = std::clamp((s - start) / length, 0.0, 1.0);
      return {path[i].x + t * (path[i + 1].x - path[i].x),
              path[i].y + t * (path[i + 1].y - path[i].y)};
    }
    start += length;
  }
  return path.back();
}

robot::Velocity PathFollower::limit(double v, double w) {
  const double dv = params_.max_linear_accel * params_.dt();
  const double dw = params_.max_angular_accel * params_.dt();
  robot::Velocity out;
  out.v = std::clamp(std::clamp(v, last_.v - dv, last_.v + dv), -params_.max_linear_speed,
                     params_.max_linear_speed);
  out.w = std::clamp(std::clamp(w, last_.w - dw, last_.w + dw), -params_.max_angular_speed,
                     params_.max_angular_speed);
  last_ = out;
  return out;
}

FollowStatus PathFollower::step(const robot::Pose2D& pose, robot::Velocity& cmd) {
  before_ = last_;
  turning_before_ = turning_in_place_;
  if (!path_ || path_->empty()) {
    last_ = cmd = robot::Velocity{};
    return FollowStatus::kNoPath;
  }
  const FollowerParams& p = params_;
  const Point2 here{pose.x, pose.y};
  deviation_ = project(here);
  const double to_goal = std::hypot(goal_.x - pose.x, goal_.y - pose.y);
  if (!at_goal_ && deviation_ > p.max_deviation) {
    last_ = cmd = robot::Velocity{};
    return FollowStatus::kStrayed;
  }
  // At the goal point only near the end of the path (a loop may pass the goal earlier).
  if (!at_goal_ && to_goal <= p.xy_tolerance &&
      total_length_ - progress_s_ <= p.xy_tolerance + p.max_deviation) {
    at_goal_ = true;
  }

  if (at_goal_) {
    const double error =
        std::isfinite(goal_.theta) ? robot::wrapAngle(goal_.theta - pose.theta) : 0;
    const double stopped_v = p.max_linear_accel * p.dt() + 1e-12;
    const double stopped_w = p.max_angular_accel * p.dt() + 1e-12;
    if (std::fabs(error) <= p.yaw_tolerance && std::fabs(last_.v) <= stopped_v &&
        std::fabs(last_.w) <= stopped_w) {
      last_ = cmd = robot::Velocity{};
      return FollowStatus::kArrived;
    }
    cmd = limit(0.0, turnRate(error, p.max_angular_speed, p.heading_gain, p.max_angular_accel));
    return FollowStatus::kFollowing;
  }

  cmd = pursue(pose, p.lookahead);
  return FollowStatus::kFollowing;
}

robot::Velocity PathFollower::retry(const robot::Pose2D& pose, double lookahead) {
  requirePositive("lookahead", lookahead);
  last_ = before_;
  turning_in_place_ = turning_before_;
  return pursue(pose, lookahead);
}

robot::Velocity PathFollower::pursue(const robot::Pose2D& pose, double lookahead) {
  const FollowerParams& p = params_;
  const double to_goal = std::hypot(goal_.x - pose.x, goal_.y - pose.y);
  const double remaining = std::max(total_length_ - progress_s_, to_goal);
  // Pure pursuit towards the carrot, in the robot's frame.
  const Point2 carrot = pointAt(progress_s_ + lookahead);
  const double dx = carrot.x - pose.x;
  const double dy = carrot.y - pose.y;
  const double c = std::cos(pose.theta);
  const double s = std::sin(pose.theta);
  const double lx = c * dx + s * dy;
  const double ly = -s * dx + c * dy;
  const double alpha = std::atan2(ly, lx);
  const double threshold = turning_in_place_ ? 0.5 * p.rotate_threshold : p.rotate_threshold;
  turning_in_place_ = std::fabs(alpha) > threshold;
  if (turning_in_place_) {
    return limit(0.0, turnRate(alpha, p.max_angular_speed, p.heading_gain, p.max_angular_accel));
  }
  const double d2 = lx * lx + ly * ly;
  const double kappa = d2 > 1e-12 ? 2.0 * ly / d2 : 0.0;
  // Brake with 80 % of the deceleration limit so the discrete ramp stops before the goal.
  double v = std::min(p.max_linear_speed, std::sqrt(1.6 * p.max_linear_accel * remaining));
  if (std::fabs(kappa) * v > p.max_angular_speed) v = p.max_angular_speed / std::fabs(kappa);
  const double dv = p.max_linear_accel * p.dt();
  v = std::clamp(v, last_.v - dv, last_.v + dv);
  return limit(v, kappa * v);
}

}  // namespace roomba_rrt::navigation
