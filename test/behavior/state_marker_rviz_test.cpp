// The behaviour's state text follows the robot in rviz: opens config/roomba_rrt.rviz on a virtual
// X server (Xvfb) while roomba_sim runs (state_marker_rviz.test), starts roomba_fsm once rviz
// draws the robot, and screenshots the first spiral (20 s of robot time in one state, the text
// sent once). In every shot the black text must sit on the blue robot disc, while the disc moves
// far more than that between the shots.
#include <gtest/gtest.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <string>
#include <vector>

#include "../common/run_node.h"
#include "../common/screen_capture.h"

namespace {

using roomba_rrt::test::Blob;
using roomba_rrt::test::Box;
using roomba_rrt::test::Rgb;
using roomba_rrt::test::Screenshot;

constexpr Rgb kFloorNotYetCleaned{100, 120, 117};  // the coverage map's unknown cells
constexpr Rgb kRobotBlue{51, 153, 230};            // roomba_sim's robot disc, lit from above
constexpr Rgb kTextBlack{0, 0, 0};                 // behavior_node.cpp's state text
constexpr int kWidth = 1000, kHeight = 640;
constexpr double kRobotRadius = 0.17;  // m, config/roomba_world.yaml
constexpr int kShots = 7;
constexpr double kSecondsBetweenShots = 1.0;  // wall clock; 2 s of robot time (×2 in the .test)

/// Pixels per metre of the top-down view in the rviz config ("Scale:" of the current view).
double viewScale(const std::string& rviz_file) {
  std::ifstream in(rviz_file);
  for (std::string line; std::getline(in, line);) {
    const std::size_t key = line.find_first_not_of(' ');
    if (key != std::string::npos && line.compare(key, 6, "Scale:") == 0) {
      return std::stod(line.substr(key + 6));
    }
  }
  return 0;
}

/// The latest state the behaviour published, and how many it published.
class StateWatch {
 public:
  void onState(const std_msgs::String& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    state_ = msg.data;
    ++messages_;
  }
  std::string state() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return state_;
  }
  int messages() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return messages_;
  }

 private:
  mutable std::mutex mutex_;
  std::string state_;
  int messages_ = 0;
};

/// What one screenshot shows in rviz's 3D view.
struct View {
  Blob robot, text;
  double distance() const { return std::hypot(text.x - robot.x, text.y - robot.y); }
};

View look(const Screenshot& shot) {
  // Only inside the room: the Displays panel has white backgrounds and blue labels.
  const Box room = shot.find(kFloorNotYetCleaned, 4, shot.all()).bounds;
  // The text is antialiased: its core is within 25 of black, which nothing else in the room is
  // (the swept floor is 214 grey: white text vanished on it).
  return {shot.find(kRobotBlue, 10, room), shot.find(kTextBlack, 25, room)};
}

TEST(StateMarkerRviz, state_text_follows_the_robot_while_it_spirals) {
  const std::string config = ros::package::getPath("roomba_rrt") + "/config/roomba_rrt.rviz";
  const double scale = viewScale(config);
  ASSERT_GT(scale, 0) << "no view scale in " << config;
  // The text is centred over the robot (top-down view): its centroid stays within the disc's
  // radius of the disc's centre, give or take the disc's marker lag (up to 0.1 s at 1 m/s, as
  // roomba_sim sends it at 10 Hz) and the part of the disc the text hides: 0.15 m.
  const double near_px = (kRobotRadius + 0.15) * scale;
  // Text left where the spiral began is more than near_px from the robot in one of two shots
  // whose robot positions are more than 2 near_px apart: ask for 3 near_px.
  const double far_px = 3 * near_px;

  roomba_rrt::test::VirtualScreen screen(kWidth, kHeight);
  ASSERT_FALSE(screen.display().empty()) << "Xvfb did not start (is the xvfb package installed?)";
  const pid_t rviz = screen.start({"rviz", "-d", config});

  ros::NodeHandle nh;
  StateWatch watch;
  ros::Subscriber sub = nh.subscribe("/roomba_fsm/state", 10, &StateWatch::onState, &watch);
  ros::AsyncSpinner spinner(1);
  spinner.start();

  // The robot stands still until a behaviour drives it: wait for rviz to draw it first.
  long robot_pixels = 0;
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(50);
       robot_pixels < 300 && ros::WallTime::now() < end;) {
    ros::WallDuration(1.0).sleep();
    robot_pixels = look(screen.grab()).robot.pixels;
  }
  if (robot_pixels < 300) roomba_rrt::test::stop(rviz);
  ASSERT_GE(robot_pixels, 300) << "rviz did not draw the robot (/roomba_sim/markers)";

  // MoveForward for 3 s of robot time (1.5 m, clear of the walls), then MoveInSpiral for 20 s.
  const pid_t fsm = roomba_rrt::test::spawn(
      {roomba_rrt::test::siblingExecutable("roomba_fsm"), "__name:=roomba_fsm"});
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(20);
       watch.state() != "MoveInSpiral" && ros::WallTime::now() < end;) {
    ros::WallDuration(0.05).sleep();
  }
  const int messages_before = watch.messages();
  ros::WallDuration(0.5).sleep();  // rviz draws the new text

  std::vector<Screenshot> shots;
  std::vector<View> views;
  for (int i = 0; i < kShots && watch.state() == "MoveInSpiral"; ++i) {
    if (i > 0) ros::WallDuration(kSecondsBetweenShots).sleep();
    shots.push_back(screen.grab());
    views.push_back(look(shots.back()));
  }
  const std::string state_after = watch.state();
  const int messages_after = watch.messages();
  roomba_rrt::test::stop(fsm);
  roomba_rrt::test::stop(rviz);

  ASSERT_EQ(state_after, "MoveInSpiral")
      << "roomba_fsm did not spiral (state: " << state_after << ")";
  ASSERT_EQ(messages_after, messages_before) << "the state changed between the shots";
  ASSERT_EQ(views.size(), std::size_t{kShots});
  double moved_px = 0;
  for (std::size_t i = 0; i < views.size(); ++i) {
    const View& v = views[i];
    for (const View& w : views) {
      moved_px = std::max(moved_px, std::hypot(v.robot.x - w.robot.x, v.robot.y - w.robot.y));
    }
    std::printf(
        "shot %zu: robot %ld px at (%.0f, %.0f), text %ld px at (%.0f, %.0f): %.1f px apart\n", i,
        v.robot.pixels, v.robot.x, v.robot.y, v.text.pixels, v.text.x, v.text.y, v.distance());
    EXPECT_GT(v.robot.pixels, 300) << "shot " << i << ": no robot disc";
    EXPECT_GT(v.text.pixels, 50) << "shot " << i << ": no state text";
    EXPECT_LT(v.distance(), near_px) << "shot " << i << ": the state text is not over the robot";
  }
  std::printf(
      "the robot was up to %.0f px apart between shots (the text must stay within %.0f px of it)\n",
      moved_px, near_px);
  EXPECT_GT(moved_px, far_px) << "the robot hardly moved: the test shows nothing";
  if (HasFailure()) {
    for (std::size_t i = 0; i < shots.size(); ++i) {
      const std::string file =
          testing::TempDir() + "state_marker_rviz_" + std::to_string(i) + ".png";
      if (shots[i].savePng(file)) std::printf("shot %zu: %s\n", i, file.c_str());
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "state_marker_rviz_test");
  return RUN_ALL_TESTS();
}
