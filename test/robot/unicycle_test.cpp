#include "roomba_rrt/robot/unicycle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using roomba_rrt::robot::clampCommand;
using roomba_rrt::robot::integrateArc;
using roomba_rrt::robot::Pose2D;
using roomba_rrt::robot::Velocity;
using roomba_rrt::robot::wrapAngle;

namespace {
constexpr double kStep = 1.0 / 60.0;

Pose2D drive(Pose2D pose, Velocity cmd, int steps) {
  for (int i = 0; i < steps; ++i) pose = integrateArc(pose, cmd, kStep);
  return pose;
}
}  // namespace

TEST(Unicycle, straight_motion_equals_closed_form) {
  const Pose2D start{1.0, 2.0, 0.3};
  const Pose2D end = drive(start, {0.5, 0.0}, 120);  // 2 s
  EXPECT_NEAR(end.x, 1.0 + 1.0 * std::cos(0.3), 1e-12);
  EXPECT_NEAR(end.y, 2.0 + 1.0 * std::sin(0.3), 1e-12);
  EXPECT_DOUBLE_EQ(end.theta, 0.3);
}

TEST(Unicycle, arc_motion_equals_closed_form_circle) {
  const Pose2D start{3.0, 2.0, 0.2};
  const double v = 0.5, w = 0.8, t = 90 * kStep;
  const Pose2D end = drive(start, {v, w}, 90);
  EXPECT_NEAR(end.x, 3.0 + v / w * (std::sin(0.2 + w * t) - std::sin(0.2)), 1e-12);
  EXPECT_NEAR(end.y, 2.0 - v / w * (std::cos(0.2 + w * t) - std::cos(0.2)), 1e-12);
  EXPECT_NEAR(end.theta, 0.2 + w * t, 1e-12);
}

TEST(Unicycle, tiny_turn_rate_uses_the_straight_line_limit) {
  const Pose2D end = integrateArc({0, 0, 0}, {1.0, 0.5e-3}, 1.0);
  EXPECT_NEAR(end.x, std::cos(0.25e-3), 1e-15);
  EXPECT_NEAR(end.y, std::sin(0.25e-3), 1e-15);
}

TEST(Unicycle, full_turn_in_place_wraps_heading_and_keeps_position) {
  const Pose2D end = drive({1, 1, 0}, {0.0, 2.0}, 60);  // 2 rad
  EXPECT_DOUBLE_EQ(end.x, 1.0);
  EXPECT_DOUBLE_EQ(end.y, 1.0);
  const Pose2D later = drive(end, {0.0, 2.0}, 60);  // 4 rad → 4 − 2π
  EXPECT_NEAR(later.theta, 4.0 - 2 * M_PI, 1e-12);
}

TEST(Clamp, spirals_first_tick_gets_two_rad_per_second) {
  const Velocity cmd = clampCommand({0.5, 0.5 / 0.2}, 1.0, 2.0);
  EXPECT_EQ(cmd.v, 0.5);
  EXPECT_EQ(cmd.w, 2.0);
}

TEST(Clamp, huge_commands_are_limited_keeping_their_sign) {
  const Velocity cmd = clampCommand({-1e9, -1e9}, 1.0, 2.0);
  EXPECT_EQ(cmd.v, -1.0);
  EXPECT_EQ(cmd.w, -2.0);
}

TEST(Clamp, nan_and_infinite_components_become_zero) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Velocity cmd = clampCommand({nan, inf}, 1.0, 2.0);
  EXPECT_EQ(cmd.v, 0.0);
  EXPECT_EQ(cmd.w, 0.0);
  EXPECT_EQ(clampCommand({0.3, nan}, 1.0, 2.0).v, 0.3);
}

TEST(WrapAngle, maps_into_minus_pi_exclusive_to_pi_inclusive) {
  EXPECT_DOUBLE_EQ(wrapAngle(M_PI), M_PI);
  EXPECT_DOUBLE_EQ(wrapAngle(-M_PI), M_PI);
  EXPECT_NEAR(wrapAngle(3 * M_PI / 2), -M_PI / 2, 1e-15);
  EXPECT_NEAR(wrapAngle(-7.0), -7.0 + 2 * M_PI, 1e-15);
  EXPECT_EQ(wrapAngle(0.25), 0.25);
}
