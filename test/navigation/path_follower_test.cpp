// The path follower on a bare unicycle (exact arcs, no walls): it converges on a straight line,
// an L-shaped path and a U-turn, never exceeds its speed and acceleration limits, stays near
// the path, and ends within its tolerances at the goal heading.
#include <gtest/gtest.h>

#include <cmath>

#include "roomba_rrt/navigation/path_follower.h"
#include "roomba_rrt/robot/unicycle.h"

namespace roomba_rrt::navigation {
namespace {

struct Drive {
  FollowStatus status = FollowStatus::kFollowing;
  robot::Pose2D pose;
  int ticks = 0;
  double max_deviation = 0;  ///< while following (before the final turn)
};

/// Drives from `start` along `path` to `goal` (at most 120 s), checking every command's limits.
Drive follow(const Path& path, const robot::Pose2D& start, const robot::Pose2D& goal,
             const FollowerParams& params = {}) {
  PathFollower follower(params);
  follower.start(path, goal);
  Drive run;
  run.pose = start;
  robot::Velocity last;
  const double dt = params.dt();
  const double eps = 1e-9;
  for (; run.ticks < 120 * 60; ++run.ticks) {
    robot::Velocity cmd;
    run.status = follower.step(run.pose, cmd);
    if (run.status != FollowStatus::kFollowing) break;
    EXPECT_TRUE(std::isfinite(cmd.v) && std::isfinite(cmd.w));
    EXPECT_LE(std::fabs(cmd.v), params.max_linear_speed + eps) << "tick " << run.ticks;
    EXPECT_LE(std::fabs(cmd.w), params.max_angular_speed + eps) << "tick " << run.ticks;
    EXPECT_LE(std::fabs(cmd.v - last.v), params.max_linear_accel * dt + eps) << run.ticks;
    EXPECT_LE(std::fabs(cmd.w - last.w), params.max_angular_accel * dt + eps) << run.ticks;
    if (!follower.turningToGoal())
      run.max_deviation = std::max(run.max_deviation, follower.deviation());
    last = cmd;
    run.pose = robot::integrateArc(run.pose, cmd, dt);
  }
  return run;
}

void expectArrived(const Drive& run, const robot::Pose2D& goal, const FollowerParams& params = {}) {
  EXPECT_EQ(run.status, FollowStatus::kArrived) << toString(run.status);
  EXPECT_LE(std::hypot(run.pose.x - goal.x, run.pose.y - goal.y), params.xy_tolerance);
  EXPECT_LE(std::fabs(robot::wrapAngle(run.pose.theta - goal.theta)), params.yaw_tolerance);
}

TEST(PathFollower, converges_on_a_straight_line_and_turns_to_the_goal_heading) {
  const Path path{{0, 0}, {2, 0}};
  const robot::Pose2D goal{2, 0, M_PI / 2};
  const Drive run = follow(path, {0, 0.05, 0}, goal);  // starts 5 cm off the line
  expectArrived(run, goal);
  EXPECT_LT(run.max_deviation, 0.06);
  // 2 m at up to 0.3 m/s with ramps: well under 15 s.
  EXPECT_LT(run.ticks, 15 * 60);
}

TEST(PathFollower, converges_on_an_l_shaped_path) {
  const Path path{{0, 0}, {2, 0}, {2, 2}};
  const robot::Pose2D goal{2, 2, M_PI / 2};
  const Drive run = follow(path, {0, 0, 0}, goal);
  expectArrived(run, goal);
  EXPECT_LT(run.max_deviation, 0.1);  // the corner is cut a little (5 cm measured)
}

TEST(PathFollower, follows_a_u_turn_without_short_cutting_it) {
  // Out and back 0.6 m apart: a follower that jumps to the nearest point would take the
  // return leg at once.
  const Path path{{0, 0}, {2, 0}, {2, 0.6}, {0, 0.6}};
  const robot::Pose2D goal{0, 0.6, M_PI};
  const Drive run = follow(path, {0, 0, 0}, goal);
  expectArrived(run, goal);
  EXPECT_LT(run.max_deviation, 0.1);
  EXPECT_GT(run.ticks, 4.6 / 0.3 * 60);  // it drove the whole 4.6 m
}

TEST(PathFollower, starting_backwards_turns_in_place_first) {
  const Path path{{0, 0}, {1, 0}};
  const robot::Pose2D goal{1, 0, 0};
  const Drive run = follow(path, {0, 0, M_PI}, goal);
  expectArrived(run, goal);
  EXPECT_LT(run.max_deviation, 0.05);
}

TEST(PathFollower, tighter_limits_are_respected_too) {
  FollowerParams slow;
  slow.max_linear_speed = 0.1;
  slow.max_angular_speed = 0.5;
  slow.max_linear_accel = 0.2;
  slow.max_angular_accel = 0.5;
  slow.xy_tolerance = 0.02;
  slow.yaw_tolerance = 0.02;
  const Path path{{0, 0}, {1, 0}, {1, 1}};
  const robot::Pose2D goal{1, 1, -M_PI / 2};
  expectArrived(follow(path, {0, 0, 0}, goal, slow), goal, slow);
}

TEST(PathFollower, a_robot_far_from_the_path_has_strayed) {
  PathFollower follower(FollowerParams{});
  const Path path{{0, 0}, {2, 0}};
  follower.start(path, {2, 0, 0});
  robot::Velocity cmd{1, 1};
  EXPECT_EQ(follower.step({1, 1.0, 0}, cmd), FollowStatus::kStrayed);
  EXPECT_EQ(cmd.v, 0.0);
  EXPECT_EQ(cmd.w, 0.0);
}

TEST(PathFollower, an_empty_path_is_reported_and_stops) {
  PathFollower follower(FollowerParams{});
  const Path empty;
  follower.start(empty, {});
  robot::Velocity cmd{1, 1};
  EXPECT_EQ(follower.step({}, cmd), FollowStatus::kNoPath);
  EXPECT_EQ(cmd.v, 0.0);
}

TEST(PathFollower, a_one_point_path_turns_in_place_to_the_heading) {
  const Path path{{1, 1}};
  const robot::Pose2D goal{1, 1, 1.0};
  expectArrived(follow(path, {1, 1, -1.0}, goal), goal);
}

TEST(PathFollower, bad_parameters_name_the_field) {
  FollowerParams p;
  p.max_angular_accel = std::nan("");
  try {
    PathFollower f(p);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("max_angular_accel: must be finite and > 0, got nan", 0),
              0u);
  }
}

}  // namespace
}  // namespace roomba_rrt::navigation
