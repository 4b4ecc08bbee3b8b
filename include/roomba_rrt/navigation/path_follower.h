// Following a planned path with the unicycle: regulated pure pursuit, then a turn in place to
// the goal's heading. ROS-free, in the style of motion_primitives.h (one step per tick).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "roomba_rrt/planning/geometry.h"
#include "roomba_rrt/robot/robot_state.h"

namespace roomba_rrt::navigation {

/// A path: points in the map frame, start first, goal last (the planner's output).
using Path = std::vector<planning::Point2>;

/// The follower's limits and tolerances (defaults suit the Roomba: the simulator clamps at
/// 1 m/s and 2 rad/s).
struct FollowerParams {
  double max_linear_speed = 0.3;   ///< m/s, |v| never exceeds it
  double max_angular_speed = 1.5;  ///< rad/s, |w| never exceeds it
  double max_linear_accel = 0.5;   ///< m/s², |Δv| per tick ≤ this · dt
  double max_angular_accel = 3.0;  ///< rad/s², |Δw| per tick ≤ this · dt
  double lookahead = 0.25;         ///< m, the pure-pursuit carrot's distance along the path
  double xy_tolerance = 0.05;      ///< m, arrival: within this of the goal point
  double yaw_tolerance = 0.05;     ///< rad, arrival: heading within this of the goal's
  double max_deviation = 0.4;      ///< m, farther from the path counts as strayed
  double rotate_threshold = 0.9;   ///< rad, turn in place first when the carrot is this far off
  double heading_gain = 3.0;       ///< 1/s, w ≤ gain · heading error when turning in place
  double rate = 60.0;              ///< ticks per second (dt = 1 / rate)

  double dt() const { return 1.0 / rate; }
};

/// The ranges the navigation node and its dynamic_reconfigure (cfg/NavFollower.cfg) accept for
/// the limits and tolerances users tune.
struct FollowerLimits {
  static constexpr double kMin = 1e-3;                 ///< speeds and tolerances ≥ this
  static constexpr double kMaxSpeed = 100;             ///< m/s and rad/s
  static constexpr double kMaxXyTolerance = 10;        ///< m
  static constexpr double kMaxYawTolerance = 3.14159;  ///< rad
};

/// Throws util::InvalidInput naming the first bad field (non-finite, or ≤ 0; the tolerances
/// and lookahead must be > 0, max_deviation > xy_tolerance; speeds at most
/// FollowerLimits::kMaxSpeed, tolerances at most their limits).
void validate(const FollowerParams& params);

/// What the follower reports after a step.
enum class FollowStatus : std::uint8_t {
  kFollowing,  ///< on the way: drive with the command
  kArrived,    ///< within xy_tolerance and yaw_tolerance, stopped: the command is zero
  kStrayed,    ///< farther than max_deviation from the path: the command is zero, replan
  kNoPath,     ///< start() was given fewer than one point
  kBlocked,    ///< GuardedFollower only: held still by its guard, the command is zero, replan
};

const char* toString(FollowStatus status);

/// Regulated pure pursuit on a polyline:
///
/// - progress: the robot's projection on the path only moves forward (searched within a window
///   ahead, so a path that passes near itself, a U-turn, is not short-cut);
/// - carrot: the point `lookahead` further along the path (the goal near the end);
/// - curvature κ = 2·y / d² to the carrot in the robot frame; v = min(max speed, √(2·a·s) with
///   s the distance left along the path (slows down to stop at the goal), max_w / |κ|), w = κ·v;
/// - a carrot more than rotate_threshold off the heading (start facing away, a sharp corner)
///   is first faced by turning in place (hysteresis: until it is within half of it);
/// - within xy_tolerance of the goal: v brakes to 0 and the robot turns in place to the goal
///   heading, braking so that it stops on it; kArrived once within yaw_tolerance and stopped.
///
/// Every command respects the speed and acceleration limits relative to the previous command
/// (start() takes the current one), except the zero command of kStrayed and kNoPath (the
/// caller stops or backs off). step() allocates nothing; start() copies nothing (the path must
/// outlive the run).
class PathFollower {
 public:
  explicit PathFollower(const FollowerParams& params);
  /// New limits and tolerances (validated; util::InvalidInput and nothing changes), used from the
  /// next step on.
  void setParams(const FollowerParams& params);

  /// Starts following `path` to `goal` (its x, y should be the path's last point; its θ is the
  /// heading to end with). `current` is the robot's command of the last tick.
  void start(const Path& path, const robot::Pose2D& goal, const robot::Velocity& current = {});

  /// One tick from the robot's pose: the status and, in `cmd`, the command for this tick.
  FollowStatus step(const robot::Pose2D& pose, robot::Velocity& cmd);
  /// The last step()'s command again, pursuing a carrot `lookahead` along the path instead of
  /// params().lookahead (> 0): a nearer carrot cuts a corner less. For a caller that may not send
  /// the first command (GuardedFollower); it replaces it. Only after a step() that returned
  /// kFollowing and was not turning to the goal's heading.
  robot::Velocity retry(const robot::Pose2D& pose, double lookahead);

  /// Distance from the robot to the path found by the last step (m).
  double deviation() const { return deviation_; }
  /// Arc length along the path of the robot's projection found by the last step (m).
  double progress() const { return progress_s_; }
  /// The point `distance` along the path beyond the robot's projection (clamped to the goal).
  planning::Point2 pointAhead(double distance) const { return pointAt(progress_s_ + distance); }
  /// True once the robot has reached the goal point and turns to the goal heading.
  bool turningToGoal() const { return at_goal_; }
  const FollowerParams& params() const { return params_; }

 private:
  /// Updates segment_, segment_start_s_ and the projection; returns the distance to the path.
  double project(const planning::Point2& p);
  /// The point at arc length `s` along the path (clamped to its ends).
  planning::Point2 pointAt(double s) const;
  /// Applies the acceleration and speed limits to (v, w) from the last command, and stores it.
  robot::Velocity limit(double v, double w);
  /// Pure pursuit of the carrot `lookahead` along the path (or turning in place towards it).
  robot::Velocity pursue(const robot::Pose2D& pose, double lookahead);

  FollowerParams params_;
  const Path* path_ = nullptr;
  robot::Pose2D goal_;
  double total_length_ = 0;
  std::size_t segment_ = 0;     ///< index of the segment the robot projects onto
  double segment_start_s_ = 0;  ///< arc length at the start of segment_
  double progress_s_ = 0;       ///< arc length of the robot's projection
  double deviation_ = 0;
  bool at_goal_ = false;
  bool turning_in_place_ = false;
  robot::Velocity last_;
  /// last_ and turning_in_place_ as the last step() found them (retry() starts from there).
  robot::Velocity before_;
  bool turning_before_ = false;
};

}  // namespace roomba_rrt::navigation
