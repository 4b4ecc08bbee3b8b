// roomba_sim refuses an invalid world at start: it exits non-zero with a message naming the bad
// parameter. Runs the real binary under the rostest master with bad private parameters.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <string>

namespace {

struct Outcome {
  int exit_code = -1;
  std::string output;
};

/// The roomba_sim built next to this test (catkin puts both in devel/lib/roomba_rrt; `rosrun`
/// would be ambiguous with several build directories inside the package).
std::string simExecutable() {
  std::array<char, 4096> self{};
  const ssize_t n = readlink("/proc/self/exe", self.data(), self.size() - 1);
  const std::string path(self.data(), n > 0 ? n : 0);
  return path.substr(0, path.rfind('/') + 1) + "roomba_sim";
}

/// Runs roomba_sim under a fresh node name with extra command-line arguments.
Outcome runSim(const std::string& name, const std::string& args) {
  const std::string command =
      "timeout 30 " + simExecutable() + " __name:=" + name + " " + args + " 2>&1";
  Outcome outcome;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return outcome;
  std::array<char, 512> buffer;
  while (fgets(buffer.data(), buffer.size(), pipe)) outcome.output += buffer.data();
  const int status = pclose(pipe);
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

void expectRefused(const Outcome& outcome, const std::string& parameter) {
  EXPECT_NE(outcome.exit_code, 0) << outcome.output;
  EXPECT_NE(outcome.exit_code, 124) << "timed out instead of exiting: " << outcome.output;
  EXPECT_NE(outcome.output.find(parameter), std::string::npos)
      << "message does not name " << parameter << ":\n"
      << outcome.output;
}

TEST(SimInvalidWorld, negative_radius_exits_naming_robot_radius) {
  expectRefused(runSim("sim_negative_radius", "_robot/radius:=-0.17"), "robot/radius");
}

TEST(SimInvalidWorld, room_smaller_than_the_robot_exits_naming_room_width) {
  expectRefused(runSim("sim_tiny_room", "_room/width:=0.2"), "room/width");
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

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "sim_invalid_world_test");
  return RUN_ALL_TESTS();
}
