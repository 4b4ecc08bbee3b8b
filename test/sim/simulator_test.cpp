#include "roomba_rrt/sim/simulator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "roomba_rrt/sim/contact.h"
#include "roomba_rrt/world/world_file.h"

using namespace roomba_rrt::robot;
using namespace roomba_rrt::sim;
using namespace roomba_rrt::world;

namespace {

const Velocity kLabForward{0.5, 0.0};  // FORWARD_SPEED

/// The lab's step order with a fixed command; returns the last bumper sensed.
BumperState run(Simulator& sim, const Velocity& cmd, int steps) {
  BumperState bumper;
  for (int i = 0; i < steps; ++i) bumper = sim.step(cmd);
  return bumper;
}

World furnishedWorld() { return loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml"); }

}  // namespace

TEST(Simulator, starts_at_the_room_centre_facing_x_with_bumper_released) {
  Simulator sim{World{}};
  EXPECT_EQ(sim.pose().x, 3.2);
  EXPECT_EQ(sim.pose().y, 2.4);
  EXPECT_EQ(sim.pose().theta, 0.0);
  EXPECT_FALSE(sim.senseContact().pressed);
}

TEST(Simulator, lab_forward_command_reaches_3_7_after_1_s_and_4_7_after_3_s) {
  Simulator sim{World{}};
  run(sim, kLabForward, 60);
  EXPECT_NEAR(sim.pose().x, 3.7, 1e-12);
  EXPECT_NEAR(sim.pose().y, 2.4, 1e-12);
  EXPECT_NEAR(sim.time(), 1.0, 1e-12);
  run(sim, kLabForward, 120);
  EXPECT_NEAR(sim.pose().x, 4.7, 1e-12);
  EXPECT_NEAR(sim.pose().y, 2.4, 1e-12);
}

TEST(Simulator, driving_straight_stops_exactly_at_the_wall_with_the_bumper_pressed) {
  Simulator sim{World{}};
  EXPECT_FALSE(run(sim, {1.0, 0.0}, 150).pressed);  // 2.5 m: 0.53 m short of contact
  const BumperState bumper = run(sim, {1.0, 0.0}, 60);
  EXPECT_EQ(sim.pose().x, 6.4 - 0.17);
  EXPECT_EQ(sim.pose().y, 2.4);
  EXPECT_TRUE(bumper.pressed);
  EXPECT_TRUE(bumper.left);  // head-on: both switches
  EXPECT_TRUE(bumper.right);
}

TEST(Simulator, pushing_on_does_not_move_and_keeps_the_bumper_pressed) {
  Simulator sim{World{}};
  run(sim, {1.0, 0.0}, 240);
  const Pose2D at_wall = sim.pose();
  for (int i = 0; i < 60; ++i) {
    EXPECT_TRUE(sim.step({1.0, 0.0}).pressed);
    EXPECT_EQ(sim.pose().x, at_wall.x);
  }
}

TEST(Simulator, backing_off_releases_the_bumper_on_the_first_step) {
  Simulator sim{World{}};
  run(sim, {1.0, 0.0}, 240);
  EXPECT_TRUE(sim.step({-0.1, 0.0}).pressed);  // sensed before the step back
  EXPECT_FALSE(sim.senseContact().pressed);
  EXPECT_NEAR(sim.pose().x, 6.4 - 0.17 - 0.1 / 60, 1e-12);
}

TEST(Simulator, sliding_along_a_wall_keeps_the_heading) {
  Simulator sim{World{}};
  sim.setPose({3.2, 4.8 - 0.17, M_PI / 4});
  run(sim, {1.0, 0.0}, 60);
  EXPECT_EQ(sim.pose().y, 4.8 - 0.17);
  EXPECT_NEAR(sim.pose().x, 3.2 + std::cos(M_PI / 4), 1e-12);
  EXPECT_EQ(sim.pose().theta, M_PI / 4);
}

TEST(Simulator, a_hit_on_the_left_of_the_front_sets_left) {
  Simulator sim{World{}};
  sim.setPose({6.0, 2.4, -M_PI / 4});  // heading down-right, the right wall on its left front
  const BumperState bumper = run(sim, {0.5, 0.0}, 120);
  EXPECT_TRUE(bumper.pressed);
  EXPECT_TRUE(bumper.left);
  EXPECT_FALSE(bumper.right);
}

TEST(Simulator, random_commands_never_leave_the_disc_inside_a_wall_or_furniture) {
  Simulator sim{furnishedWorld()};
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> v(-1.5, 1.5), w(-3.0, 3.0);
  std::uniform_int_distribution<int> hold(1, 30);
  for (int command = 0; command < 100000; ++command) {
    const Velocity cmd{v(rng), w(rng)};
    for (int i = hold(rng); i > 0; --i) {
      sim.step(cmd);
      const Pose2D& p = sim.pose();
      ASSERT_FALSE(penetrates(sim.world(), p.x, p.y))
          << "command " << command << " left the disc at (" << p.x << ", " << p.y << ")";
    }
  }
  EXPECT_GT(sim.coverage(), 0.5);  // the random walk reached most of the room
}

TEST(Simulator, nan_command_stops_the_robot_and_keeps_the_state_finite) {
  Simulator sim{World{}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  run(sim, {nan, nan}, 10);
  EXPECT_EQ(sim.pose().x, 3.2);
  EXPECT_TRUE(std::isfinite(sim.pose().theta));
  EXPECT_EQ(sim.lastCommand().v, 0.0);
}

TEST(Simulator, huge_commands_move_at_the_speed_limits) {
  Simulator sim{World{}};
  run(sim, {100.0, 0.0}, 30);
  EXPECT_NEAR(sim.pose().x, 3.2 + 0.5, 1e-12);
  EXPECT_EQ(sim.lastCommand().v, 1.0);
}

TEST(Simulator, coverage_of_a_straight_one_metre_sweep_is_2r_plus_pi_r_squared) {
  Simulator sim{World{}};
  run(sim, {1.0, 0.0}, 60);  // 1 m to (4.2, 2.4)
  const CoverageGrid& grid = sim.coverageGrid();
  const double cell = grid.cellSize(), r = sim.world().robot().radius;
  const double swept_area = grid.sweptFreeCells() * cell * cell;
  EXPECT_NEAR(swept_area, 2 * r * 1.0 + M_PI * r * r, 1.0 * cell);  // within one cell row
  EXPECT_NEAR(sim.coverage(), swept_area / (6.4 * 4.8), 1e-12);
}

TEST(Simulator, reset_restores_the_initial_pose_and_clears_coverage) {
  Simulator sim{World{}};
  const double initial_coverage = sim.coverage();
  run(sim, {0.7, 0.9}, 300);
  sim.reset();
  EXPECT_EQ(sim.pose().x, 3.2);
  EXPECT_EQ(sim.pose().y, 2.4);
  EXPECT_EQ(sim.pose().theta, 0.0);
  EXPECT_EQ(sim.steps(), 0);
  EXPECT_EQ(sim.coverage(), initial_coverage);
}

TEST(Simulator, set_pose_into_furniture_is_pushed_out_and_nan_pose_is_rejected) {
  Simulator sim{furnishedWorld()};
  sim.setPose({1.3, 3.5 - 0.1, 0.0});  // inside the round table
  EXPECT_FALSE(penetrates(sim.world(), sim.pose().x, sim.pose().y));
  EXPECT_TRUE(sim.senseContact().pressed);
  EXPECT_THROW(sim.setPose({std::nan(""), 1.0, 0.0}), std::invalid_argument);
}

TEST(Simulator, rejects_an_invalid_world) {
  World world;
  world.robot().radius = -0.1;
  EXPECT_THROW(Simulator{world}, std::invalid_argument);
}
