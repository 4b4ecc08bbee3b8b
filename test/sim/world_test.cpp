#include "roomba_rrt/sim/world.h"

#include <gtest/gtest.h>

#include <string>

using roomba_rrt::sim::loadWorld;
using roomba_rrt::sim::parseWorld;
using roomba_rrt::sim::World;

namespace {
/// The message parseWorld throws for `yaml`, or "" when it loads.
std::string errorFor(const std::string& yaml) {
  try {
    parseWorld(yaml, "test.yaml");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(World, default_file_is_the_labs_empty_room) {
  const World world = loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world.yaml");
  EXPECT_EQ(world.width, 6.4);
  EXPECT_EQ(world.height, 4.8);
  EXPECT_EQ(world.robot_radius, 0.17);
  EXPECT_EQ(world.max_linear_speed, 1.0);
  EXPECT_EQ(world.max_angular_speed, 2.0);
  EXPECT_EQ(world.step, 1.0 / 60.0);
  EXPECT_EQ(world.initial_pose.x, 3.2);
  EXPECT_EQ(world.initial_pose.y, 2.4);
  EXPECT_TRUE(world.circles.empty());
  EXPECT_TRUE(world.rectangles.empty());
  EXPECT_EQ(world.command_timeout, 0.5);
}

TEST(World, furnished_file_has_five_pieces) {
  const World world = loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml");
  EXPECT_EQ(world.circles.size() + world.rectangles.size(), 5u);
}

TEST(World, missing_keys_keep_the_lab_defaults) {
  const World world = parseWorld("robot: {radius: 0.2}");
  EXPECT_EQ(world.robot_radius, 0.2);
  EXPECT_EQ(world.width, 6.4);
}

TEST(World, negative_radius_is_named) {
  EXPECT_NE(errorFor("robot: {radius: -0.17}").find("robot/radius"), std::string::npos);
}

TEST(World, room_smaller_than_the_robot_is_named) {
  EXPECT_NE(errorFor("room: {width: 0.3, height: 4.8}").find("room/width"), std::string::npos);
}

TEST(World, initial_pose_inside_a_wall_is_named) {
  EXPECT_NE(errorFor("initial_pose: {x: 0.1, y: 2.4}").find("initial_pose"), std::string::npos);
}

TEST(World, initial_pose_inside_furniture_is_named) {
  const std::string error = errorFor("furniture: {circles: [{x: 3.2, y: 2.4, radius: 0.3}]}");
  EXPECT_NE(error.find("initial_pose"), std::string::npos);
}

TEST(World, bad_furniture_is_named_with_its_index) {
  const std::string error = errorFor(
      "furniture: {rectangles: [{min_x: 0, min_y: 0, max_x: 1, max_y: 1},"
      " {min_x: 2, min_y: 0, max_x: 1, max_y: 1}]}");
  EXPECT_NE(error.find("furniture/rectangles[1]/max_x"), std::string::npos) << error;
  EXPECT_NE(errorFor("furniture: {circles: [{x: 1, y: 1, radius: 0}]}")
                .find("furniture/circles[0]/radius"),
            std::string::npos);
}

TEST(World, misspelt_key_is_named_not_ignored) {
  EXPECT_NE(errorFor("robot: {raduis: 0.2}").find("robot/raduis"), std::string::npos);
}

TEST(World, value_of_the_wrong_type_is_named) {
  EXPECT_NE(errorFor("step: fast").find("step"), std::string::npos);
}

TEST(World, messages_start_with_the_source_and_unreadable_files_are_named) {
  EXPECT_EQ(errorFor("robot: {radius: -1}").rfind("test.yaml: robot/radius", 0), 0u);
  try {
    loadWorld("/nonexistent/world.yaml");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/world.yaml"), std::string::npos);
  }
}

// Named robots (issue 13).

TEST(World, without_robots_the_world_has_one_unnamed_robot_from_the_shared_fields) {
  const World world = loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world.yaml");
  EXPECT_TRUE(world.robots.empty());
  const auto robots = roomba_rrt::sim::robotsOf(world);
  ASSERT_EQ(robots.size(), 1u);
  EXPECT_EQ(robots[0].name, "");
  EXPECT_EQ(robots[0].radius, world.robot_radius);
  EXPECT_EQ(robots[0].initial_pose.x, 3.2);
  EXPECT_EQ(robots[0].max_linear_speed, 1.0);
}

TEST(World, two_robots_file_names_two_robots_in_the_lab_room) {
  const World world = loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_two_robots.yaml");
  ASSERT_EQ(world.robots.size(), 2u);
  EXPECT_EQ(world.robots[0].name, "robot1");
  EXPECT_EQ(world.robots[1].name, "robot2");
  EXPECT_EQ(world.robots[0].initial_pose.x, 1.6);
  EXPECT_EQ(world.robots[1].radius, 0.17);
  EXPECT_EQ(world.width, 6.4);
}

TEST(World, robots_take_the_shared_limits_unless_they_override_them) {
  const World world = parseWorld(
      "robot: {radius: 0.2, max_linear_speed: 0.8}\n"
      "robots:\n"
      "  - {name: a, initial_pose: {x: 1, y: 1}}\n"
      "  - {name: b, initial_pose: {x: 3, y: 1, theta: 1.5}, radius: 0.1, max_angular_speed: 1}\n");
  EXPECT_EQ(world.robots[0].radius, 0.2);
  EXPECT_EQ(world.robots[0].max_linear_speed, 0.8);
  EXPECT_EQ(world.robots[1].radius, 0.1);
  EXPECT_EQ(world.robots[1].max_linear_speed, 0.8);
  EXPECT_EQ(world.robots[1].max_angular_speed, 1.0);
  EXPECT_EQ(world.robots[1].initial_pose.theta, 1.5);
}

TEST(World, bad_robot_lists_are_named) {
  const std::string a = "  - {name: a, initial_pose: {x: 1, y: 1}}\n";
  EXPECT_NE(errorFor("robots:\n  - {initial_pose: {x: 1, y: 1}}\n").find("robots[0]/name"),
            std::string::npos);
  EXPECT_NE(errorFor("robots:\n" + a + a).find("repeats 'a'"), std::string::npos);
  EXPECT_NE(
      errorFor("robots:\n  - {name: 1x, initial_pose: {x: 1, y: 1}}\n").find("robots[0]/name"),
      std::string::npos);
  EXPECT_NE(
      errorFor("robots:\n  - {name: a/b, initial_pose: {x: 1, y: 1}}\n").find("robots[0]/name"),
      std::string::npos);
  EXPECT_NE(errorFor("robots:\n" + a + "  - {name: b, initial_pose: {x: 1.2, y: 1}}\n")
                .find("puts b on top of a"),
            std::string::npos);
  EXPECT_NE(errorFor("robots:\n  - {name: a, initial_pose: {x: 0.1, y: 1}}\n")
                .find("robots[0]/initial_pose"),
            std::string::npos);
  EXPECT_NE(errorFor("robots:\n  - {name: a, initial_pose: {x: 1, y: 1}, radius: -1}\n")
                .find("robots[0]/radius"),
            std::string::npos);
  EXPECT_NE(errorFor("robots:\n  - {name: a, initial_pose: {x: 1, y: 1}, colour: red}\n")
                .find("robots[0]/colour"),
            std::string::npos);
  EXPECT_NE(errorFor("initial_pose: {x: 1, y: 1}\nrobots:\n" + a).find("initial_pose cannot"),
            std::string::npos);
}
