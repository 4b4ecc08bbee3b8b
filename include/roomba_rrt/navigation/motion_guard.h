// Never touch what the robot knows: a command is checked against the same exact geometry the
// simulator bumps against before it is sent, and slowed down (to turning in place, if need be)
// when the step it starts would bring the disc too close to a wall or a piece of furniture.
#pragma once

#include "roomba_rrt/planning/problem.h"
#include "roomba_rrt/robot/robot_state.h"

namespace roomba_rrt::navigation {

/// A safety filter for a disc robot on a unicycle. The followed path keeps `clearance` from
/// every obstacle, but pure pursuit cuts corners inside it; on one goal in a few thousand that
/// was enough to touch a table (seed 3, furnished room). filter() rolls the command forward along
/// its arc over the distance it would take to stop (at `max_linear_accel`) plus one tick (or
/// `ticks`), and requires every point of the way to keep the disc at least `margin` from the
/// walls and furniture; otherwise it returns the largest safe fraction of the linear speed with
/// the same angular speed.
/// Turning in place never changes what a disc covers, so a safe command always exists. A robot
/// already closer than `margin` (pushed there) may still move away: only steps that bring it closer
/// are cut.
class MotionGuard {
 public:
  /// `world`: the room and furniture (bounds, obstacles, rectangles; its robot_radius is the
  /// disc, its start, goal and clearance are not used). `ticks`: how many ticks at the command's
  /// speed come before the braking (more: for a pose that may be older than the follower expects).
  /// util::InvalidInput naming the field for a rate or acceleration that is not positive, a
  /// margin or radius that is negative, or fewer than one tick.
  MotionGuard(planning::Problem world, double rate, double max_linear_accel, double margin = 0.01,
              int ticks = 1);

  /// The command to send instead of `cmd` at `pose`.
  robot::Velocity filter(const robot::Pose2D& pose, const robot::Velocity& cmd) const;

  /// Distance from the disc centred at (x, y) to the nearest wall or piece of furniture, minus
  /// the radius: the gap (negative when overlapping).
  double gap(double x, double y) const;

 private:
  bool safe(const robot::Pose2D& pose, double v, double w) const;

  planning::Problem world_;
  double dt_;
  double max_linear_accel_;
  double margin_;
  int ticks_;
};

}  // namespace roomba_rrt::navigation
