#include "roomba_rrt/sim/contact.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace roomba_rrt::robot;
using namespace roomba_rrt::sim;
using namespace roomba_rrt::world;

namespace {
World furnishedRoom() {
  World world;
  world.room.circles = {{2.0, 2.0, 0.5}};
  world.room.rectangles = {{5.0, 0.0, 6.4, 1.0}};
  return world;
}
}  // namespace

TEST(ResolvePenetration, pushes_back_onto_a_wall_along_its_normal) {
  const World world;
  double x = 6.4 - 0.1, y = 2.0;
  ASSERT_TRUE(resolvePenetration(world, x, y));
  EXPECT_EQ(x, 6.4 - 0.17);
  EXPECT_EQ(y, 2.0);
}

TEST(ResolvePenetration, pushes_out_of_a_circle_along_the_radius) {
  const World world = furnishedRoom();
  double x = 2.0 + 0.4 * std::cos(1.0), y = 2.0 + 0.4 * std::sin(1.0);
  ASSERT_TRUE(resolvePenetration(world, x, y));
  EXPECT_NEAR(x, 2.0 + 0.67 * std::cos(1.0), 1e-12);
  EXPECT_NEAR(y, 2.0 + 0.67 * std::sin(1.0), 1e-12);
  EXPECT_FALSE(penetrates(world, x, y));
}

TEST(ResolvePenetration, settles_in_the_corner_between_furniture_and_wall) {
  const World world = furnishedRoom();
  double x = 6.35, y = 1.05;  // into the cupboard's top and the right wall at once
  ASSERT_TRUE(resolvePenetration(world, x, y));
  EXPECT_NEAR(x, 6.4 - 0.17, 1e-12);
  EXPECT_NEAR(y, 1.0 + 0.17, 1e-12);
}

TEST(ResolvePenetration, reports_a_gap_narrower_than_the_robot) {
  World world;
  world.room.rectangles = {{0.0, 0.0, 3.0, 2.3}, {0.0, 2.5, 3.0, 4.8}};  // a 0.2 m slot
  double x = 1.0, y = 2.4;
  EXPECT_FALSE(resolvePenetration(world, x, y));
}

TEST(SenseBumper, touching_counts_and_a_gap_releases) {
  const World world;
  EXPECT_TRUE(senseBumper(world, {6.4 - 0.17, 2.4, 0.0}).pressed);
  EXPECT_FALSE(senseBumper(world, {6.4 - 0.17 - 1e-3, 2.4, 0.0}).pressed);
}

TEST(SenseBumper, head_on_hit_closes_both_switches) {
  const BumperState bumper = senseBumper(World{}, {6.4 - 0.17, 2.4, 0.0});
  EXPECT_TRUE(bumper.left);
  EXPECT_TRUE(bumper.right);
}

TEST(SenseBumper, hit_on_the_left_of_the_front_closes_left_only) {
  // Facing 45° to the right of the wall's normal: the wall is on the robot's left front.
  const BumperState bumper = senseBumper(World{}, {6.4 - 0.17, 2.4, -M_PI / 4});
  EXPECT_TRUE(bumper.pressed);
  EXPECT_TRUE(bumper.left);
  EXPECT_FALSE(bumper.right);
}

TEST(SenseBumper, furniture_on_the_right_closes_right_only) {
  const World world = furnishedRoom();
  // The table's centre is straight ahead-right (bearing −60°) at contact distance.
  const double bearing = -M_PI / 3, d = 0.67;
  const Pose2D pose{2.0 - d * std::cos(bearing), 2.0 - d * std::sin(bearing), 0.0};
  const BumperState bumper = senseBumper(world, pose);
  EXPECT_TRUE(bumper.pressed);
  EXPECT_FALSE(bumper.left);
  EXPECT_TRUE(bumper.right);
}
