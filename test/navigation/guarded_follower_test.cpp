// The follower behind its guard, as the cleaning drives it: 0.5 m/s, 1 cm from the furniture, a
// guard that keeps half of that. Where pure pursuit cuts a corner inside the path's clearance,
// the guard refuses the step, and a nearer carrot takes the corner instead of a stop.
#include <gtest/gtest.h>

#include <cmath>

#include "roomba_rrt/navigation/guarded_follower.h"
#include "roomba_rrt/robot/unicycle.h"
#include "roomba_rrt/util/require.h"

namespace roomba_rrt::navigation {
namespace {

constexpr double kRadius = 0.17;
constexpr double kClearance = 0.01;

FollowerParams cleaningParams() {
  FollowerParams p;
  p.max_linear_speed = 0.5;
  p.max_linear_accel = 2.0;
  p.max_angular_speed = 2.0;
  p.max_angular_accel = 16.0;
  p.heading_gain = 8.0;
  p.lookahead = 0.2;
  p.xy_tolerance = 0.01;
  p.yaw_tolerance = 0.1;
  return p;
}

struct Lap {
  FollowStatus status = FollowStatus::kFollowing;
  int stops = 0;         ///< times the robot came to a standstill before the goal
  double closest = 1e9;  ///< smallest gap to the box or the walls (m)
  robot::Pose2D pose;
};

/// Drives `path` from its first point (facing along it) with the guard of `world`.
Lap drive(const planning::Problem& world, const Path& path, const FollowerParams& params) {
  const auto guard = std::make_shared<const MotionGuard>(world, params.rate,
                                                         params.max_linear_accel, kClearance / 2);
  GuardedFollower follower(params, guard);
  const robot::Pose2D goal{path.back().x, path.back().y, std::nan("")};
  follower.start(path, goal, {});
  Lap run;
  run.pose = {path[0].x, path[0].y, std::atan2(path[1].y - path[0].y, path[1].x - path[0].x)};
  bool moving = false;
  for (int tick = 0; tick < 60 * 60; ++tick) {
    robot::Velocity cmd;
    run.status = follower.step(run.pose, cmd);
    if (run.status != FollowStatus::kFollowing) break;
    EXPECT_TRUE(std::isfinite(cmd.v) && std::isfinite(cmd.w)) << "tick " << tick;
    const bool goal_near = std::hypot(run.pose.x - goal.x, run.pose.y - goal.y) < 0.1;
    if (moving && cmd.v == 0 && !goal_near) ++run.stops;
    moving = cmd.v != 0;
    run.pose = robot::integrateArc(run.pose, cmd, params.dt());
    run.closest = std::min(run.closest, guard->gap(run.pose.x, run.pose.y));
  }
  return run;
}

TEST(GuardedFollower, passes_over_a_cabinet_at_the_clearance_without_stopping) {
  planning::Problem world;
  world.bounds = {0, 5, 0, 5};
  world.rectangles = {{2.0, 1.0, 2.6, 1.6}};  // a cabinet in the middle of the room
  world.robot_radius = kRadius;
  // A cleaning row 8 cm too close to its top: the way over it, 1 cm from it (as the coverage
  // planner's lattice paths go), and on along the row. Pure pursuit cuts the corners where the
  // way over levels out, towards the cabinet's corners: the guard stopped it 4 times.
  const double y = 1.6 + kRadius + kClearance;
  const Path path{{1.0, y - 0.08}, {1.7, y - 0.08}, {1.95, y},
                  {2.65, y},       {2.9, y - 0.08}, {3.6, y - 0.08}};
  const Lap run = drive(world, path, cleaningParams());
  EXPECT_EQ(run.status, FollowStatus::kArrived) << toString(run.status);
  EXPECT_EQ(run.stops, 0);
  EXPECT_GE(run.closest, kClearance / 2 - 1e-9);  // never inside the guard's margin
}

TEST(GuardedFollower, a_nearer_carrot_is_the_same_pursuit_and_keeps_the_limits) {
  // PathFollower::retry: the same command for the same carrot, and a nearer carrot on an L path
  // before its corner turns less than the step's farther one.
  PathFollower follower(cleaningParams());
  const Path path{{0, 0}, {1, 0}, {1, 1}};
  follower.start(path, {1, 1, std::nan("")}, {0.5, 0});
  const robot::Pose2D before_corner{0.9, 0, 0};
  robot::Velocity cmd;
  ASSERT_EQ(follower.step(before_corner, cmd), FollowStatus::kFollowing);
  const robot::Velocity again = follower.retry(before_corner, 0.2);
  EXPECT_DOUBLE_EQ(again.v, cmd.v);
  EXPECT_DOUBLE_EQ(again.w, cmd.w);
  EXPECT_GT(cmd.w, 0.1);  // the carrot is round the corner: turning left
  const robot::Velocity nearer = follower.retry(before_corner, 0.05);
  EXPECT_LT(std::fabs(nearer.w), 1e-9);  // the carrot is still on the first leg
  const FollowerParams p = cleaningParams();
  EXPECT_LE(std::fabs(nearer.v - 0.5), p.max_linear_accel * p.dt() + 1e-12);  // from 0.5 m/s
  try {
    follower.retry(before_corner, 0.0);
    FAIL() << "a zero lookahead was accepted";
  } catch (const util::InvalidInput& e) {
    EXPECT_EQ(e.field(), "lookahead");
  }
}

}  // namespace
}  // namespace roomba_rrt::navigation
