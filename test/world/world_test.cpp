#include "roomba_rrt/world/world.h"
#include "../common/shared_maps.h"
#include "roomba_rrt/world/world_file.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "../common/hostile_yaml.h"

using roomba_rrt::world::loadWorld;
using roomba_rrt::world::parseWorld;
using roomba_rrt::world::World;

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
  EXPECT_EQ(world.room.width, 6.4);
  EXPECT_EQ(world.room.height, 4.8);
  EXPECT_EQ(world.robot().radius, 0.17);
  EXPECT_EQ(world.robot().max_linear_speed, 1.0);
  EXPECT_EQ(world.robot().max_angular_speed, 2.0);
  EXPECT_EQ(world.step, 1.0 / 60.0);
  EXPECT_EQ(world.robot().initial_pose.x, 3.2);
  EXPECT_EQ(world.robot().initial_pose.y, 2.4);
  EXPECT_TRUE(world.room.circles.empty());
  EXPECT_TRUE(world.room.rectangles.empty());
  const roomba_rrt::world::SimulatorSettings simulator =
      roomba_rrt::world::readWorldFile(ROOMBA_RRT_CONFIG_DIR "/roomba_world.yaml").simulator;
  EXPECT_EQ(simulator.command_timeout, 0.5);
  EXPECT_EQ(simulator.real_time_factor, 1.0);
}

TEST(World, furnished_file_has_five_pieces) {
  const World world = loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml");
  EXPECT_EQ(world.room.circles.size() + world.room.rectangles.size(), 5u);
}

TEST(World, missing_keys_keep_the_lab_defaults) {
  const World world = parseWorld("robot: {radius: 0.2}");
  EXPECT_EQ(world.robot().radius, 0.2);
  EXPECT_EQ(world.room.width, 6.4);
}

TEST(World, negative_radius_is_named) {
  EXPECT_NE(errorFor("robot: {radius: -0.17}").find("robot.radius"), std::string::npos);
}

TEST(World, room_smaller_than_the_robot_is_named) {
  EXPECT_NE(errorFor("room: {width: 0.3, height: 4.8}").find("room.width"), std::string::npos);
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
  EXPECT_NE(error.find("furniture.rectangles[1].max_x"), std::string::npos) << error;
  EXPECT_NE(errorFor("furniture: {circles: [{x: 1, y: 1, radius: 0}]}")
                .find("furniture.circles[0].radius"),
            std::string::npos);
}

TEST(World, misspelt_key_is_named_not_ignored) {
  EXPECT_NE(errorFor("robot: {raduis: 0.2}").find("robot.raduis"), std::string::npos);
}

TEST(World, value_of_the_wrong_type_is_named) {
  EXPECT_NE(errorFor("step: fast").find("step"), std::string::npos);
}

TEST(World, messages_start_with_the_source_and_unreadable_files_are_named) {
  EXPECT_EQ(errorFor("robot: {radius: -1}").rfind("test.yaml: robot.radius: ", 0), 0u);
  try {
    loadWorld("/nonexistent/world.yaml");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/world.yaml"), std::string::npos);
  }
}

// Issue 11: these aborted with std::bad_alloc, hung for minutes or threw std::ios_failure.
TEST(World, sizes_that_the_coverage_grid_cannot_hold_are_named) {
  EXPECT_NE(errorFor("room: {width: 1e5, height: 1e5}")
                .find("room.width: must be "
                      "in (0, 1000], got 100000"),
            std::string::npos);
  EXPECT_NE(errorFor("room: {width: 6.4, height: 1e300}").find("room.height"), std::string::npos);
  EXPECT_NE(errorFor("coverage_cell_size: 1e-9")
                .find("coverage_cell_size: must be in "
                      "[0.001, 1], got 1e-09"),
            std::string::npos);
  EXPECT_NE(errorFor("coverage_cell_size: 5e-324").find("coverage_cell_size"), std::string::npos);
  // In range on its own, but 1e12 cells together: the message says why.
  const std::string error =
      errorFor("room: {width: 1000, height: 1000}\ncoverage_cell_size: 0.001");
  EXPECT_NE(error.find("coverage_cell_size: (0.001) is too small"), std::string::npos) << error;
  EXPECT_NE(errorFor("robot: {radius: 1e300}")
                .find("robot.radius: must be in "
                      "(0, 10], got 1e+300"),
            std::string::npos);
}

TEST(World, a_world_too_large_for_the_default_coverage_cell_gets_a_coarser_one) {
  // Nav2's 100 m x 100 m benchmark map at 0.025 m would need 1.6e7 cells: the simulator refused
  // it unless the user knew to set coverage_cell_size.
  EXPECT_EQ(parseWorld("room: {width: 6.4, height: 4.8}").coverage_cell_size, 0.025);
  EXPECT_EQ(parseWorld("room: {width: 100, height: 100}\ninitial_pose: {x: 50, y: 50}")
                .coverage_cell_size,
            0.05);
  EXPECT_EQ(parseWorld("room: {width: 300, height: 300}\ninitial_pose: {x: 50, y: 50}")
                .coverage_cell_size,
            0.1);
  EXPECT_FALSE(parseWorld("room: {width: 6.4, height: 4.8}").coverage_cell_size_given);
  EXPECT_TRUE(parseWorld("coverage_cell_size: 0.05").coverage_cell_size_given);
  // A cell the file sets is the user's: kept, and refused when too small.
  EXPECT_NE(errorFor("room: {width: 100, height: 100}\ninitial_pose: {x: 50, y: 50}\n"
                     "coverage_cell_size: 0.025")
                .find("coverage_cell_size: (0.025) is too small"),
            std::string::npos);
  ROOMBA_RRT_REQUIRE_SHARED_MAP("nav2_bench_100by100_15");
  const std::string map = ::roomba_rrt::test::sharedMapPath("nav2_bench_100by100_15");
  EXPECT_EQ(roomba_rrt::world::readWorldFile(map).world.coverage_cell_size, 0.05);
}

TEST(World, a_node_that_takes_the_pose_from_elsewhere_accepts_an_initial_pose_in_a_wall) {
  World world = parseWorld("furniture: {circles: [{x: 1, y: 1, radius: 0.5}]}");
  world.robot().initial_pose = {1.0, 1.0, 0.0};
  EXPECT_THROW(roomba_rrt::world::validate(world), std::invalid_argument);
  EXPECT_NO_THROW(roomba_rrt::world::validate(world, roomba_rrt::world::PoseSource::kElsewhere));
  world.robot().initial_pose.x = 1e300;  // its coordinates are still checked
  EXPECT_THROW(roomba_rrt::world::validate(world, roomba_rrt::world::PoseSource::kElsewhere),
               std::invalid_argument);
}

TEST(World, a_large_room_within_the_limits_loads) {
  const World world = parseWorld(
      "room: {width: 1000, height: 1000}\ncoverage_cell_size: 0.5\n"
      "initial_pose: {x: 500, y: 500}");
  EXPECT_EQ(world.room.width, 1000);
}

TEST(World, node_parameters_outside_their_ranges_are_named) {
  EXPECT_NE(errorFor("real_time_factor: 1e-300")
                .find("real_time_factor: must be in "
                      "[0.0001, 10000], got 1e-300"),
            std::string::npos);
  EXPECT_NE(errorFor("real_time_factor: 1e5").find("real_time_factor"), std::string::npos);
  EXPECT_NE(errorFor("step: 1e-300").find("step: must be in [0.0001, 1], got 1e-300"),
            std::string::npos);
  EXPECT_NE(errorFor("robot: {max_linear_speed: 1e9}").find("robot.max_linear_speed"),
            std::string::npos);
  EXPECT_NE(errorFor("command_timeout: 1e300").find("command_timeout"), std::string::npos);
  EXPECT_NE(errorFor("initial_pose: {x: 3.2, y: 2.4, theta: 1e300}").find("initial_pose.theta"),
            std::string::npos);
  EXPECT_EQ(errorFor("real_time_factor: 1e-4"), "");
  EXPECT_EQ(errorFor("real_time_factor: 1e4"), "");
}

TEST(World, too_much_furniture_is_named) {
  std::string yaml = "furniture:\n  circles:\n";
  for (int i = 0; i < 1001; ++i) yaml += "  - {x: 0.1, y: 0.1, radius: 0.01}\n";
  EXPECT_NE(errorFor(yaml).find("furniture.circles: has 1001 entries; at most 1000"),
            std::string::npos);
  EXPECT_NE(errorFor("furniture: {circles: [{x: 1e300, y: 1, radius: 0.1}]}")
                .find("furniture.circles[0].x"),
            std::string::npos);
}

TEST(World, a_path_that_is_not_a_small_regular_file_is_named) {
  const auto message = [](const std::string& path) {
    try {
      loadWorld(path);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string directory = std::filesystem::temp_directory_path().string();
  EXPECT_NE(message(directory).find("not a regular file"), std::string::npos);
  const std::string big = directory + "/roomba_rrt_world_test_big.yaml";
  {
    std::ofstream out(big);
    out << "# " << std::string(2 << 20, 'x') << "\n";
  }
  EXPECT_NE(message(big).find("at most 1048576"), std::string::npos) << message(big);
  std::remove(big.c_str());
  const std::string empty = directory + "/roomba_rrt_world_test_empty.yaml";
  std::ofstream(empty).close();
  EXPECT_EQ(message(empty), "");  // an empty file keeps every default
  std::remove(empty.c_str());
}
// Named robots (issue 13).

TEST(World, without_robots_the_world_has_one_unnamed_robot_from_the_shared_fields) {
  const World world = loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world.yaml");
  EXPECT_FALSE(world.namedRobots());
  const auto& robots = world.robots;
  ASSERT_EQ(robots.size(), 1u);
  EXPECT_EQ(robots[0].name, "");
  EXPECT_EQ(robots[0].radius, world.robot().radius);
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
  EXPECT_EQ(world.room.width, 6.4);
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
  EXPECT_NE(errorFor("robots:\n  - {initial_pose: {x: 1, y: 1}}\n").find("robots[0].name"),
            std::string::npos);
  EXPECT_NE(errorFor("robots:\n" + a + a).find("repeats 'a'"), std::string::npos);
  EXPECT_NE(
      errorFor("robots:\n  - {name: 1x, initial_pose: {x: 1, y: 1}}\n").find("robots[0].name"),
      std::string::npos);
  EXPECT_NE(
      errorFor("robots:\n  - {name: a/b, initial_pose: {x: 1, y: 1}}\n").find("robots[0].name"),
      std::string::npos);
  EXPECT_NE(errorFor("robots:\n" + a + "  - {name: b, initial_pose: {x: 1.2, y: 1}}\n")
                .find("puts b on top of a"),
            std::string::npos);
  EXPECT_NE(errorFor("robots:\n  - {name: a, initial_pose: {x: 0.1, y: 1}}\n")
                .find("robots[0].initial_pose"),
            std::string::npos);
  EXPECT_NE(errorFor("robots:\n  - {name: a, initial_pose: {x: 1, y: 1}, radius: -1}\n")
                .find("robots[0].radius"),
            std::string::npos);
  EXPECT_NE(errorFor("robots:\n  - {name: a, initial_pose: {x: 1, y: 1}, colour: red}\n")
                .find("robots[0].colour"),
            std::string::npos);
  EXPECT_NE(errorFor("initial_pose: {x: 1, y: 1}\nrobots:\n" + a).find("initial_pose: cannot"),
            std::string::npos);
}

// Issue 20, item 3: YAML's duplicate keys would slip past the "unknown keys are errors" rule.
TEST(World, a_key_given_twice_is_refused_naming_it_and_both_lines) {
  EXPECT_EQ(errorFor("robot:\n  radius: 0.17\nroom: {width: 5}\nrobot:\n  radious: 0.2\n"),
            "test.yaml: robot: is given twice (lines 1 and 4); a mapping holds one value per key");
  EXPECT_EQ(errorFor("room:\n  width: 5\n  width: 6\n"),
            "test.yaml: room.width: is given twice (lines 2 and 3); a mapping holds one value "
            "per key");
  EXPECT_EQ(errorFor("furniture:\n  circles:\n    - {x: 1, y: 1, radius: 0.2, x: 2}\n"),
            "test.yaml: furniture.circles[0].x: is given twice (lines 3 and 3); a mapping holds "
            "one value per key");
}

// Issue 44, item 1: an alias made the nodes a cycle (SIGSEGV after 12 s) or a billion leaves
// (70 min for 9 levels); both are refused at the anchor, before anything walks the nodes.
TEST(World, anchors_and_aliases_are_refused_naming_the_line) {
  using roomba_rrt::test::aliasBomb;
  using roomba_rrt::test::aliasRefusal;
  EXPECT_EQ(errorFor(roomba_rrt::test::kRecursiveAlias), "test.yaml: " + aliasRefusal(1, 7));
  EXPECT_EQ(errorFor("room: {width: 6.4, height: 4.8}\n" + aliasBomb(9)),
            "test.yaml: " + aliasRefusal(2, 5));
  EXPECT_EQ(errorFor("room: {width: 6.4, height: 4.8}\nrobot: {radius: &r 0.2}\n"),
            "test.yaml: " + aliasRefusal(2, 17));
  // Found by world_fuzzer: a stray leading ',' made the alias check read empty documents for
  // ever. yaml-cpp reads such a file as an empty document, as it did before the check: the
  // defaults, which defaultsNotice() reports.
  EXPECT_EQ(errorFor(",robot: {radius: 0.2}\n"), "");
}

// Issue 44, item 4: a key without a value meant 0 (a rectangle's min_y) or the default; a
// furniture piece without a coordinate ran with 0.
TEST(World, a_key_present_needs_a_value_and_furniture_every_coordinate) {
  EXPECT_EQ(errorFor("furniture:\n  rectangles:\n    - {min_x: 1, max_x: 2, max_y: 2}\n"),
            "test.yaml: furniture.rectangles[0].min_y: is missing");
  EXPECT_EQ(errorFor("furniture:\n  rectangles:\n    - {min_x: 1, min_y: null, max_x: 2, "
                     "max_y: 2}\n"),
            "test.yaml: furniture.rectangles[0].min_y: has no value; give a number or remove the "
            "key");
  EXPECT_EQ(errorFor("furniture: {circles: [{x: 1, y: 1, radius: ~}]}\n"),
            "test.yaml: furniture.circles[0].radius: has no value; give a number or remove the "
            "key");
  EXPECT_EQ(errorFor("furniture: {circles: [{x: 1, radius: 0.2}]}\n"),
            "test.yaml: furniture.circles[0].y: is missing");
  EXPECT_EQ(errorFor("robot:\n  radius:\n"),
            "test.yaml: robot.radius: has no value; give a number or remove the key");
  EXPECT_EQ(errorFor("step: ~\n"),
            "test.yaml: step: has no value; give a number or remove the key");
  EXPECT_EQ(errorFor("room:\n"), "test.yaml: room: has no value; give a mapping");
  EXPECT_EQ(errorFor("furniture: {circles: [~]}\n"),
            "test.yaml: furniture.circles[0]: has no value; give a mapping");
  EXPECT_EQ(errorFor("furniture: {rectangles: }\n"),
            "test.yaml: furniture.rectangles: has no value; give a list or remove the key");
  EXPECT_EQ(errorFor("robots:\n  - {name: a, initial_pose: ~}\n"),
            "test.yaml: robots[0].initial_pose: has no value; give a mapping");
  // Absent keys keep their defaults, as before.
  EXPECT_EQ(errorFor("robot: {radius: 0.2}\n"), "");
}

TEST(World, a_file_that_sets_no_section_says_which_defaults_it_runs_with) {
  const World empty = parseWorld("# truncated to a comment\n", "cut.yaml");
  EXPECT_EQ(roomba_rrt::world::defaultsNotice(empty, "cut.yaml"),
            "cut.yaml sets no room, furniture, robot, initial_pose: the defaults are used "
            "(room.width 6.4, room.height 4.8, no furniture, robot.radius 0.17, "
            "robot.max_linear_speed 1, robot.max_angular_speed 2, initial_pose.x 3.2, "
            "initial_pose.y 2.4, initial_pose.theta 0)");
  const World furnished =
      roomba_rrt::world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml");
  EXPECT_EQ(roomba_rrt::world::defaultsNotice(furnished, "f.yaml"), "");
  const World robot_only = parseWorld("robot: {radius: 0.2}\nroom: {width: 6}\n", "r.yaml");
  EXPECT_EQ(roomba_rrt::world::defaultsNotice(robot_only, "r.yaml"),
            "r.yaml sets no furniture, initial_pose: the defaults are used (no furniture, "
            "initial_pose.x 3.2, initial_pose.y 2.4, initial_pose.theta 0)");
}
