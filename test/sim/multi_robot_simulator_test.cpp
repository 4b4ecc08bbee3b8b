#include "roomba_rrt/sim/multi_robot_simulator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "roomba_rrt/sim/contact.h"
#include "roomba_rrt/sim/simulator.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/world/world_file.h"

using namespace roomba_rrt::robot;
using namespace roomba_rrt::sim;
using namespace roomba_rrt::world;

namespace {

World furnishedWorld() { return loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml"); }

World twoRobots(const Pose2D& a, const Pose2D& b) {
  World world;
  world.robots = {RobotSpec{"robot1", a}, RobotSpec{"robot2", b}};
  return world;
}

/// A random command of the lab behaviour's kinds, with some beyond the limits.
Velocity randomCommand(std::mt19937& rng) {
  std::uniform_real_distribution<double> v(-1.5, 1.5), w(-3.0, 3.0);
  return {v(rng), w(rng)};
}

}  // namespace

TEST(MultiRobotSimulator, one_unnamed_robot_is_bit_identical_to_the_simulator) {
  const World world = furnishedWorld();
  Simulator single(world);
  MultiRobotSimulator multi(world);
  ASSERT_EQ(multi.size(), 1u);
  std::mt19937 rng(3);
  std::vector<Velocity> command(1);
  for (int i = 0; i < 100000; ++i) {
    if (i % 97 == 0) command[0] = randomCommand(rng);
    const BumperState expected = single.senseContact();
    multi.senseContact();
    ASSERT_EQ(multi.bumper(0).pressed, expected.pressed) << "step " << i;
    ASSERT_EQ(multi.bumper(0).left, expected.left) << "step " << i;
    ASSERT_EQ(multi.bumper(0).right, expected.right) << "step " << i;
    single.move(command[0]);
    multi.move(command);
    ASSERT_EQ(multi.pose(0).x, single.pose().x) << "step " << i;
    ASSERT_EQ(multi.pose(0).y, single.pose().y) << "step " << i;
    ASSERT_EQ(multi.pose(0).theta, single.pose().theta) << "step " << i;
  }
  EXPECT_EQ(multi.coverageGrid(0).sweptFreeCells(), single.coverageGrid().sweptFreeCells());
  EXPECT_EQ(multi.unionCoverage(), single.coverage());
  EXPECT_EQ(multi.time(), single.time());
}

TEST(MultiRobotSimulator, two_robots_driven_head_on_stop_at_contact_with_both_bumpers_pressed) {
  MultiRobotSimulator sim(twoRobots({2.0, 2.4, 0.0}, {4.4, 2.4, M_PI}));
  const std::vector<Velocity> forward = {{0.5, 0.0}, {0.5, 0.0}};
  for (int i = 0; i < 300; ++i) sim.step(forward);  // 5 s: they meet after about 2 s
  sim.senseContact();
  const double gap = std::hypot(sim.pose(1).x - sim.pose(0).x, sim.pose(1).y - sim.pose(0).y);
  EXPECT_NEAR(gap, 0.34, 1e-9);
  EXPECT_GE(gap, 0.34 - 1e-9);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_TRUE(sim.bumper(i).pressed) << i;
    EXPECT_TRUE(sim.bumper(i).left) << i;  // head-on: both switches
    EXPECT_TRUE(sim.bumper(i).right) << i;
    EXPECT_NEAR(sim.pose(i).y, 2.4, 1e-12) << i;
  }
  const Pose2D a = sim.pose(0), b = sim.pose(1);
  sim.step(forward);  // pushing on does not move either
  EXPECT_EQ(sim.pose(0).x, a.x);
  EXPECT_EQ(sim.pose(1).x, b.x);
  sim.step({{-0.1, 0.0}, {0.0, 0.0}});  // robot1 backs off: both bumpers release
  sim.senseContact();
  EXPECT_FALSE(sim.bumper(0).pressed);
  EXPECT_FALSE(sim.bumper(1).pressed);
}

TEST(MultiRobotSimulator, a_robot_hit_on_its_right_side_presses_only_its_right_switch) {
  // robot1 faces +y; robot2 drives at it from its right (+x), facing −x.
  MultiRobotSimulator sim(twoRobots({2.0, 2.4, M_PI / 2}, {3.0, 2.4, M_PI}));
  for (int i = 0; i < 200; ++i) sim.step({{0.0, 0.0}, {0.5, 0.0}});
  sim.senseContact();
  EXPECT_TRUE(sim.bumper(0).pressed);
  EXPECT_TRUE(sim.bumper(0).right);
  EXPECT_FALSE(sim.bumper(0).left);
  EXPECT_TRUE(sim.bumper(1).left && sim.bumper(1).right);  // robot2 hit it head-on
  EXPECT_EQ(sim.pose(0).x, 2.0);  // a robot is an obstacle: it is not pushed away
  EXPECT_EQ(sim.pose(0).y, 2.4);
}

TEST(MultiRobotSimulator, ten_robots_never_overlap_over_1e5_random_commands) {
  World world = furnishedWorld();
  world.robots = spreadRobots(world, 10);
  MultiRobotSimulator sim(world);
  ASSERT_EQ(sim.size(), 10u);
  std::mt19937 rng(11);
  std::vector<Velocity> commands(sim.size());
  long contacts = 0;
  for (int i = 0; i < 10000; ++i) {
    for (Velocity& c : commands) c = randomCommand(rng);  // 10 × 10^4 = 10^5 commands
    for (int hold = 0; hold < 6; ++hold) {
      sim.step(commands);
      for (std::size_t a = 0; a < sim.size(); ++a) {
        const Pose2D& p = sim.pose(a);
        ASSERT_FALSE(penetrates(world, p.x, p.y)) << "robot " << a << " step " << i;
        for (std::size_t b = 0; b < a; ++b) {
          const double d = std::hypot(p.x - sim.pose(b).x, p.y - sim.pose(b).y);
          ASSERT_GE(d, 2 * world.robot().radius - 1e-9) << a << " overlaps " << b << " step " << i;
          contacts += d <= 2 * world.robot().radius + kContactTolerance;
        }
      }
    }
  }
  EXPECT_GT(contacts, 1000);  // the robots did meet, often
  for (std::size_t a = 0; a < sim.size(); ++a) {
    EXPECT_TRUE(std::isfinite(sim.pose(a).theta));
    EXPECT_LE(sim.coverage(a), sim.unionCoverage());
  }
}

TEST(MultiRobotSimulator, coverage_is_per_robot_and_for_the_union) {
  MultiRobotSimulator sim(twoRobots({1.0, 1.0, 0.0}, {1.0, 3.5, 0.0}));
  for (int i = 0; i < 240; ++i) sim.step({{0.5, 0.0}, {0.5, 0.0}});
  const double a = sim.coverage(0), b = sim.coverage(1);
  EXPECT_GT(a, 0.01);
  EXPECT_NEAR(a, b, 1e-3);                         // the same sweep, apart from rounding
  EXPECT_NEAR(sim.unionCoverage(), a + b, 1e-12);  // disjoint sweeps add up
  EXPECT_EQ(sim.unionCoverageGrid().sweptFreeCells(),
            sim.coverageGrid(0).sweptFreeCells() + sim.coverageGrid(1).sweptFreeCells());
}

TEST(MultiRobotSimulator, reset_set_pose_and_bad_command_lists) {
  MultiRobotSimulator sim(twoRobots({1.0, 1.0, 0.0}, {3.0, 1.0, 0.0}));
  EXPECT_THROW(sim.move({{0.5, 0.0}}), std::invalid_argument);
  sim.setPose(1, {1.1, 1.0, 0.0});  // onto robot1: pushed out to touch it
  EXPECT_NEAR(std::hypot(sim.pose(1).x - 1.0, sim.pose(1).y - 1.0), 0.34, 1e-9);
  EXPECT_THROW(sim.setPose(0, {NAN, 1.0, 0.0}), std::invalid_argument);
  for (int i = 0; i < 60; ++i) sim.step({{0.5, 0.3}, {0.5, -0.3}});
  sim.reset();
  EXPECT_EQ(sim.pose(1).x, 3.0);
  EXPECT_EQ(sim.pose(0).x, 1.0);
  EXPECT_EQ(sim.steps(), 0);
  EXPECT_EQ(sim.spec(1).name, "robot2");
}

TEST(MultiRobotSimulator, a_speed_limit_too_fast_for_the_step_is_refused_naming_the_speed) {
  MultiRobotSimulator sim(twoRobots({1.0, 1.0, 0.0}, {3.0, 1.0, 0.0}));
  try {
    sim.setSpeedLimits(50, 2);  // 50 m/s * 1/60 s is more than the radius of 0.17 m
    FAIL() << "50 m/s accepted";
  } catch (const roomba_rrt::util::InvalidInput& e) {
    EXPECT_EQ(e.field(), "max_linear_speed") << e.what();
    EXPECT_NE(std::string(e.what()).find("must be below 10.2 m/s"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("got 50"), std::string::npos) << e.what();
  }
  EXPECT_EQ(sim.world().robot().max_linear_speed, 1.0);  // the limit in force is kept
  sim.setSpeedLimits(10, 2);
  EXPECT_EQ(sim.world().robot().max_linear_speed, 10.0);
}

TEST(SpreadRobots, one_robot_stands_at_the_labs_room_centre_two_in_the_halves) {
  const World world;
  const auto one = spreadRobots(world, 1);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].initial_pose.x, 3.2);
  EXPECT_EQ(one[0].initial_pose.y, 2.4);
  const auto two = spreadRobots(world, 2);
  EXPECT_EQ(two[0].initial_pose.x, 1.6);
  EXPECT_DOUBLE_EQ(two[1].initial_pose.x, 4.8);
  EXPECT_EQ(two[1].name, "robot2");
}

TEST(SpreadRobots, a_hundred_fit_in_the_furnished_room_and_too_many_are_refused) {
  World world = furnishedWorld();
  world.robots = spreadRobots(world, 100);
  EXPECT_NO_THROW(MultiRobotSimulator{world});
  EXPECT_THROW(spreadRobots(world, 400), std::invalid_argument);
}
