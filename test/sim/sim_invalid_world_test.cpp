// roomba_sim refuses an invalid world at start: it exits non-zero with a message naming the bad
// parameter. Runs the real binary under the rostest master with bad private parameters.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "../common/run_node.h"

namespace {

using roomba_rrt::test::Outcome;

/// Runs roomba_sim under a fresh node name with extra command-line arguments.
Outcome runSim(const std::string& name, const std::string& args) {
  return roomba_rrt::test::runNode("roomba_sim", name, args);
}

void expectRefused(const Outcome& outcome, const std::string& parameter) {
  EXPECT_NE(outcome.exit_code, 0) << outcome.output;
  EXPECT_NE(outcome.exit_code, 124) << "timed out instead of exiting: " << outcome.output;
  EXPECT_NE(outcome.output.find(parameter), std::string::npos)
      << "message does not name " << parameter << ":\n"
      << outcome.output;
}

TEST(SimInvalidWorld, negative_radius_exits_naming_robot_radius) {
  expectRefused(runSim("sim_negative_radius", "_robot/radius:=-0.17"), "robot.radius");
}

TEST(SimInvalidWorld, room_smaller_than_the_robot_exits_naming_room_width) {
  expectRefused(runSim("sim_tiny_room", "_room/width:=0.2"), "room.width");
}

TEST(SimInvalidWorld, initial_pose_inside_furniture_exits_naming_initial_pose) {
  const std::string file = "/tmp/roomba_rrt_bad_world_" + std::to_string(getpid()) + ".yaml";
  std::ofstream(file) << "furniture:\n  circles:\n    - {x: 3.2, y: 2.4, radius: 0.5}\n";
  expectRefused(runSim("sim_pose_in_table", "_world_file:=" + file), "initial_pose");
  std::remove(file.c_str());
}

TEST(SimInvalidWorld, missing_world_file_exits_naming_the_file) {
  expectRefused(runSim("sim_no_file", "_world_file:=/nonexistent/world.yaml"),
                "/nonexistent/world.yaml");
}

TEST(SimInvalidWorld, parameter_of_the_wrong_type_exits_naming_it) {
  expectRefused(runSim("sim_word_factor", "_real_time_factor:=fast"), "real_time_factor");
}

// Issue 11: these aborted with std::bad_alloc or std::ios_failure, or ran for minutes.
TEST(SimInvalidWorld, a_room_too_large_for_the_coverage_grid_exits_naming_room_width) {
  expectRefused(runSim("sim_huge_room", "_room/width:=1e5 _room/height:=1e5"), "room.width");
}

TEST(SimInvalidWorld, a_coverage_cell_too_small_exits_naming_coverage_cell_size) {
  expectRefused(runSim("sim_tiny_cell", "_coverage_cell_size:=1e-9"), "coverage_cell_size");
  expectRefused(runSim("sim_many_cells",
                       "_room/width:=1000 _room/height:=1000 "
                       "_coverage_cell_size:=0.001"),
                "coverage_cell_size");
}

TEST(SimInvalidWorld, a_huge_robot_exits_naming_robot_radius) {
  expectRefused(runSim("sim_huge_robot", "_robot/radius:=1e300"), "robot.radius");
}

TEST(SimInvalidWorld, a_directory_as_world_file_exits_naming_it) {
  expectRefused(runSim("sim_directory", "_world_file:=/tmp"), "/tmp: cannot read the world file");
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "sim_invalid_world_test");
  return RUN_ALL_TESTS();
}
