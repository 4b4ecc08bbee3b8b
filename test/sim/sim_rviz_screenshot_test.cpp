// rviz with config/roomba_rrt.rviz really shows the simulation: starts a virtual X server (Xvfb),
// opens rviz on it while roomba_sim runs (sim_rviz.test), grabs the screen with ImageMagick's
// `import` and looks for the robot's disc, the coverage map and the LDS's scan in the pixels.
#include <gtest/gtest.h>
#include <ros/package.h>
#include <ros/ros.h>

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "../common/screen_capture.h"

namespace {

using roomba_rrt::test::Rgb;

// Colours rviz draws (see roomba_sim_node.cpp and rviz's "map" palette, 80 % over the background).
constexpr Rgb kRobotBlue{51, 153, 230};
constexpr Rgb kFloorNotYetCleaned{100, 120, 117};
constexpr Rgb kWallGrey{140, 140, 140};
constexpr Rgb kScanMagenta{255, 60, 200};  // the LaserScan display's flat colour
constexpr int kWidth = 1000, kHeight = 640;

using roomba_rrt::test::Box;

/// The box of the rows and columns holding at least `least` pixels near `colour`: a large area's
/// own, without the few pixels of that colour elsewhere (in rviz's panels' text).
Box solidBounds(const roomba_rrt::test::Screenshot& shot, Rgb colour, int least) {
  std::vector<int> columns(shot.width), rows(shot.height);
  for (int y = 0; y < shot.height; ++y) {
    for (int x = 0; x < shot.width; ++x) {
      if (shot.isNear(x, y, colour, 10)) ++columns[x], ++rows[y];
    }
  }
  const auto span = [&](const std::vector<int>& counts, int& lo, int& hi) {
    lo = 0, hi = 0;
    for (int k = 0; k < static_cast<int>(counts.size()); ++k) {
      if (counts[k] < least) continue;
      if (hi == 0) lo = k;
      hi = k + 1;
    }
  };
  Box box;
  span(columns, box.x0, box.x1);
  span(rows, box.y0, box.y1);
  return box;
}

TEST(SimRviz, rviz_config_shows_the_robot_the_walls_the_coverage_map_and_the_scan) {
  roomba_rrt::test::VirtualScreen screen(kWidth, kHeight);
  ASSERT_FALSE(screen.display().empty()) << "Xvfb did not start (is the xvfb package installed?)";
  const std::string config = ros::package::getPath("roomba_rrt") + "/config/roomba_rrt.rviz";
  const pid_t rviz = screen.start({"rviz", "-d", config});

  long robot = 0, floor = 0, walls = 0, scan = 0;
  roomba_rrt::test::Screenshot shot;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(90);
  while (ros::WallTime::now() < deadline) {
    ros::WallDuration(2.0).sleep();
    shot = screen.grab();
    robot = shot.countNear(kRobotBlue);
    floor = shot.countNear(kFloorNotYetCleaned);
    walls = shot.countNear(kWallGrey, 4);
    scan = shot.countNear(kScanMagenta);
    if (robot > 300 && floor > 50000 && walls > 1000 && scan > 300) break;
  }
  roomba_rrt::test::stop(rviz);
  std::printf("on screen: robot %ld px, floor not yet cleaned %ld px, walls %ld px, scan %ld px\n",
              robot, floor, walls, scan);
  EXPECT_FALSE(shot.empty()) << "screen grab failed";
  // The screen judged, to look at (the pixel counts cannot tell a scan on the walls from one
  // beside them).
  const std::string file = testing::TempDir() + "sim_rviz.png";
  if (shot.savePng(file)) std::printf("screen: %s\n", file.c_str());
  EXPECT_GT(robot, 300) << "the robot's disc (/roomba_sim/markers) is not on screen";
  EXPECT_GT(floor, 50000) << "the coverage map (/roomba_sim/coverage_map) is not on screen";
  EXPECT_GT(walls, 1000) << "the walls (/roomba_sim/markers) are not on screen";
  EXPECT_GT(scan, 300) << "the LDS's points on the walls (/scan) are not on screen";
  // ... and on the walls: along each of the four (the robot at the room's centre sees them all
  // within 3.5 m), nowhere over the floor between them. The floor's bounds are the room's inside.
  const Box room = solidBounds(shot, kFloorNotYetCleaned, 100);
  constexpr int kBand = 15;  // px each side of a wall's face
  const Box between{room.x0 + kBand, room.y0 + kBand, room.x1 - kBand, room.y1 - kBand};
  EXPECT_EQ(shot.find(kScanMagenta, 10, between).pixels, 0) << "scan points over the floor";
  const std::pair<const char*, Box> faces[] = {
      {"left", {room.x0 - kBand, room.y0, room.x0 + kBand, room.y1}},
      {"right", {room.x1 - kBand, room.y0, room.x1 + kBand, room.y1}},
      {"top", {room.x0, room.y0 - kBand, room.x1, room.y0 + kBand}},
      {"bottom", {room.x0, room.y1 - kBand, room.x1, room.y1 + kBand}}};
  for (const auto& [side, face] : faces) {
    EXPECT_GT(shot.find(kScanMagenta, 10, face).pixels, 50) << "no scan on the " << side << " wall";
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "sim_rviz_screenshot_test");
  return RUN_ALL_TESTS();
}
