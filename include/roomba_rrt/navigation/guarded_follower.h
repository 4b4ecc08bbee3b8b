// The path follower as the robot drives it: PathFollower's command checked by the MotionGuard
// first. The one follower of navigation (FollowPath) and cleaning (FollowCoverage). ROS-free.
#pragma once

#include <memory>
#include <string>

#include "roomba_rrt/navigation/motion_guard.h"
#include "roomba_rrt/navigation/path_follower.h"

namespace roomba_rrt::navigation {

/// PathFollower behind a MotionGuard:
///
/// - the follower's command goes out when the guard lets it pass unchanged;
/// - when the guard would slow or stop it, pure pursuit is cutting a corner too close to
///   something: the same pursuit of a nearer carrot (half, then a quarter of the lookahead),
///   which cuts the corner less, goes out instead if the guard lets it pass unchanged, else the
///   guard's slowed command. In the cleaning's U-turns and ways round islands, a robot 1 cm from
///   the furniture, this kept 33 of the 40 stops the guard made in the turtlebot3 arena's rows;
/// - when the guard stops a forward command all the same, the robot follows the path closely
///   instead (it keeps its clearance), aiming at the path just ahead, turning in place first,
///   then creeping if the guard agrees, until the follower's own forward command passes the
///   guard unchanged;
/// - held by the guard for half a second (facing the path and refused even the creep), the path
///   cannot be followed from here without touching something: step() returns kBlocked (zero
///   command), so that the caller replans.
///
/// Without a guard (null) the follower's commands go out unchecked.
class GuardedFollower {
 public:
  GuardedFollower(const FollowerParams& params, std::shared_ptr<const MotionGuard> guard);

  /// The guard from now on (null: commands unchecked).
  void setGuard(std::shared_ptr<const MotionGuard> guard) { guard_ = std::move(guard); }
  /// PathFollower::setParams.
  void setParams(const FollowerParams& params) { follower_.setParams(params); }
  /// PathFollower::start; the count of ticks held still goes on (resetHold() clears it).
  void start(const Path& path, const robot::Pose2D& goal, const robot::Velocity& current) {
    follower_.start(path, goal, current);
  }
  /// Forgets how long the guard has held the robot and ends close following (a new run of the
  /// leaf).
  void resetHold() {
    held_ticks_ = 0;
    close_ = false;
  }

  /// One tick: PathFollower::step's status (and kBlocked), the command to send in `cmd`.
  FollowStatus step(const robot::Pose2D& pose, robot::Velocity& cmd);

  /// Why following `what` ("path", "leg") failed with `status` (kBlocked, kStrayed, kNoPath):
  /// "blocked: following the path would touch a known obstacle", "strayed 0.42 m from the path",
  /// "the path is empty".
  std::string failure(FollowStatus status, const std::string& what) const;

  double deviation() const { return follower_.deviation(); }
  double progress() const { return follower_.progress(); }
  const FollowerParams& params() const { return follower_.params(); }

 private:
  /// Close following's command; `held`: the guard keeps the robot from advancing (it stands, or
  /// only finishes facing a path it may not drive along).
  robot::Velocity closely(const robot::Pose2D& pose, bool& held) const;

  /// Fractions of the lookahead tried, in order, when the guard refuses the follower's command.
  static constexpr double kNearerCarrots[] = {0.5, 0.25};
  static constexpr double kCloseLookahead = 0.05;  ///< m: the path just ahead, when guarded
  static constexpr double kAligned = 0.15;         ///< rad: facing it closely enough to drive
  static constexpr double kCreepSpeed = 0.1;       ///< m/s: how fast, then
  static constexpr int kMaxHeldTicks = 30;         ///< ticks held still by the guard: kBlocked

  PathFollower follower_;
  std::shared_ptr<const MotionGuard> guard_;  ///< null: commands unchecked
  int held_ticks_ = 0;                        ///< consecutive ticks the guard stopped the robot
  bool close_ = false;                        ///< following the path closely
};

}  // namespace roomba_rrt::navigation
