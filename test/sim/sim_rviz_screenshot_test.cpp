// rviz with config/roomba_rrt.rviz really shows the simulation: starts a virtual X server (Xvfb),
// opens rviz on it while roomba_sim runs (sim_rviz.test), grabs the screen with ImageMagick's
// `import` and looks for the robot's disc and the coverage map in the pixels.
#include <gtest/gtest.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

struct Rgb {
  int r, g, b;
};
// Colours rviz draws (see roomba_sim_node.cpp and rviz's "map" palette, 80 % over the background).
constexpr Rgb kRobotBlue{51, 153, 230};
constexpr Rgb kFloorNotYetCleaned{100, 120, 117};
constexpr Rgb kWallGrey{140, 140, 140};
constexpr int kWidth = 1000, kHeight = 640;

/// Starts `args` in the background with extra environment settings; returns its pid.
pid_t spawn(const std::vector<std::string>& args, const std::vector<std::string>& env,
            int stdout_fd = -1) {
  const pid_t pid = fork();
  if (pid == 0) {
    for (const std::string& e : env) putenv(const_cast<char*>(e.c_str()));
    if (stdout_fd >= 0) dup2(stdout_fd, STDOUT_FILENO);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

void stop(pid_t pid) {
  if (pid <= 0) return;
  kill(pid, SIGTERM);
  waitpid(pid, nullptr, 0);
}

/// The screen of `display` as packed 8-bit RGB, empty when the grab failed.
std::vector<unsigned char> grabScreen(const std::string& display) {
  const std::string command =
      "DISPLAY=" + display + " import -window root -depth 8 rgb:- 2>/dev/null";
  std::vector<unsigned char> pixels;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return pixels;
  std::array<unsigned char, 65536> buffer;
  std::size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    pixels.insert(pixels.end(), buffer.begin(), buffer.begin() + n);
  }
  pclose(pipe);
  return pixels;
}

long countNear(const std::vector<unsigned char>& rgb, Rgb colour, int tolerance = 10) {
  long count = 0;
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
    if (std::abs(rgb[i] - colour.r) <= tolerance && std::abs(rgb[i + 1] - colour.g) <= tolerance &&
        std::abs(rgb[i + 2] - colour.b) <= tolerance) {
      ++count;
    }
  }
  return count;
}

TEST(SimRviz, rviz_config_shows_the_robot_the_walls_and_the_coverage_map) {
  // Xvfb picks a free display number and writes it to the pipe (-displayfd).
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const std::string screen = std::to_string(kWidth) + "x" + std::to_string(kHeight) + "x24";
  const pid_t xvfb = spawn(
      {"Xvfb", "-displayfd", std::to_string(fds[1]), "-screen", "0", screen, "-nolisten", "tcp"},
      {}, -1);
  close(fds[1]);
  char number[16] = {0};
  const ssize_t got = read(fds[0], number, sizeof(number) - 1);
  close(fds[0]);
  ASSERT_GT(got, 0) << "Xvfb did not start (is the xvfb package installed?)";
  const std::string display = ":" + std::string(number, number + got - (number[got - 1] == '\n'));

  const std::string config = ros::package::getPath("roomba_rrt") + "/config/roomba_rrt.rviz";
  const pid_t rviz =
      spawn({"rviz", "-d", config}, {"DISPLAY=" + display, "LIBGL_ALWAYS_SOFTWARE=1"}, -1);

  long robot = 0, floor = 0, walls = 0;
  std::vector<unsigned char> pixels;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(90);
  while (ros::WallTime::now() < deadline) {
    ros::WallDuration(2.0).sleep();
    pixels = grabScreen(display);
    robot = countNear(pixels, kRobotBlue);
    floor = countNear(pixels, kFloorNotYetCleaned);
    walls = countNear(pixels, kWallGrey, 4);
    if (robot > 300 && floor > 50000 && walls > 1000) break;
  }
  stop(rviz);
  stop(xvfb);
  std::printf("on screen: robot %ld px, floor not yet cleaned %ld px, walls %ld px\n", robot, floor,
              walls);
  EXPECT_EQ(pixels.size(), std::size_t{3} * kWidth * kHeight) << "screen grab failed";
  EXPECT_GT(robot, 300) << "the robot's disc (/roomba_sim/markers) is not on screen";
  EXPECT_GT(floor, 50000) << "the coverage map (/roomba_sim/coverage_map) is not on screen";
  EXPECT_GT(walls, 1000) << "the walls (/roomba_sim/markers) are not on screen";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "sim_rviz_screenshot_test");
  return RUN_ALL_TESTS();
}
