// Issue 20, item 2: the robot never touches what it knows. Seed 3 once pressed the bumper on one
// goal of 200 in the furnished room (pure pursuit cut the bench's corner inside the path's
// clearance); the MotionGuard now checks every commanded step against the walls and furniture.
// Every seed 1-20, 200 random goals each, in the furnished room and two rooms with other
// furniture: no bumper press, every goal reached. Deterministic (inline planner, seeded goals);
// about 30 s in Release.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "nav_eval_run.h"
#include "roomba_rrt/navigation/motion_guard.h"
#include "roomba_rrt/world/world.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::navigation {
namespace {

class BumpFreeNavigation : public ::testing::TestWithParam<std::string> {};

TEST_P(BumpFreeNavigation, no_seed_presses_the_bumper_and_every_goal_is_reached) {
  const world::World world = world::loadWorld(GetParam());
  for (std::uint32_t seed = 1; seed <= 20; ++seed) {
    tools::NavEvalOptions options;
    options.goals = 200;
    options.seed = seed;
    const tools::NavEvalReport report =
        tools::evaluateNavigation(world, ROOMBA_RRT_CONFIG_DIR "/roomba_nav_tree.xml", options);
    EXPECT_EQ(report.bumps, 0) << "seed " << seed;
    EXPECT_EQ(report.reached_pct, 100.0) << "seed " << seed;
  }
}

INSTANTIATE_TEST_SUITE_P(Rooms, BumpFreeNavigation,
                         ::testing::Values(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml",
                                           ROOMBA_RRT_TEST_DIR "/navigation/worlds/dining.yaml",
                                           ROOMBA_RRT_TEST_DIR "/navigation/worlds/office.yaml"));

TEST(MotionGuard, refuses_limits_it_cannot_keep_naming_them) {
  planning::Problem world;
  world.bounds = {0, 4, 0, 4};
  world.robot_radius = 0.17;
  try {
    MotionGuard(world, 60, 0.0);
    FAIL() << "a zero acceleration was accepted";
  } catch (const util::InvalidInput& e) {
    EXPECT_EQ(e.field(), "max_linear_accel");
    EXPECT_STREQ(e.what(), "max_linear_accel: must be finite and > 0, got 0");
  }
  world.robot_radius = std::nan("");
  EXPECT_THROW(MotionGuard(world, 60, 0.5), util::InvalidInput);
}

TEST(MotionGuard, slows_a_step_that_would_touch_and_never_stops_a_turn_in_place) {
  planning::Problem world;
  world.bounds = {0, 4, 0, 4};
  world.rectangles = {{2.0, 1.0, 3.0, 3.0}};
  world.robot_radius = 0.17;
  const MotionGuard guard(world, 60, 0.5);
  // 5 cm from the box, heading into it at 0.3 m/s: it would stop 9 cm later, inside the box.
  const robot::Pose2D facing{2.0 - 0.17 - 0.05, 2.0, 0.0};
  const robot::Velocity slowed = guard.filter(facing, {0.3, 0.0});
  EXPECT_LT(slowed.v, 0.3);
  EXPECT_GE(slowed.v, 0.0);
  EXPECT_EQ(guard.filter(facing, {0.0, 1.5}).w, 1.5);  // turning in place is always let through
  const robot::Velocity away = guard.filter(facing, {-0.3, 0.0});  // backing away is let through
  EXPECT_EQ(away.v, -0.3);
  // Far from everything, nothing changes.
  const robot::Velocity free = guard.filter({1.0, 2.0, 0.0}, {0.3, 0.2});
  EXPECT_EQ(free.v, 0.3);
  EXPECT_EQ(free.w, 0.2);
  EXPECT_NEAR(guard.gap(1.0, 2.0), 1.0 - 0.17, 1e-12);
}

TEST(MotionGuard, with_more_ticks_it_stops_sooner_for_a_pose_that_may_be_late) {
  planning::Problem world;
  world.bounds = {0, 4, 0, 4};
  world.robot_radius = 0.17;
  // Heading for the right wall at 0.5 m/s with 2 m/s² of braking: 6.25 cm to stop, 0.83 cm a
  // tick at 60 Hz. 8.5 cm away with a 1 cm margin: one tick and the braking (7.1 cm) leave
  // 1.4 cm; three (8.75 cm) would touch.
  const robot::Pose2D pose{4.0 - 0.17 - 0.085, 2.0, 0.0};
  const MotionGuard one(world, 60, 2.0, 0.01), three(world, 60, 2.0, 0.01, 3);
  EXPECT_EQ(one.filter(pose, {0.5, 0.0}).v, 0.5);
  EXPECT_LT(three.filter(pose, {0.5, 0.0}).v, 0.5);
  EXPECT_GT(three.filter(pose, {0.5, 0.0}).v, 0.3);
  try {
    MotionGuard(world, 60, 2.0, 0.01, 0);
    FAIL() << "no tick was accepted";
  } catch (const util::InvalidInput& e) {
    EXPECT_EQ(e.field(), "ticks");
  }
}

}  // namespace
}  // namespace roomba_rrt::navigation
