// roomba_teleop: drive the simulated Roomba from the keyboard. The terminal is read without
// echo, key by key; keyboard_teleop.h says what each key does. The command is published on
// cmd_vel at 10 Hz (roomba_sim stops a robot after 0.5 s without one), the bumper is read from
// bumper, and both are shown on one line. Quitting, a signal or a lost terminal (the window
// closed, ssh dropped) publishes a stop before the node exits.
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

#include "../ros/node_params.h"
#include "roomba_rrt/Bumper.h"
#include "roomba_rrt/teleop/keyboard_teleop.h"
#include "roomba_rrt/util/invalid_input.h"

namespace {

using roomba_rrt::robot::BumperState;
using roomba_rrt::robot::Velocity;
namespace teleop = roomba_rrt::teleop;

std::atomic<bool> g_signalled{false};
void onSignal(int) { g_signalled = true; }

// Puts the terminal in non-canonical mode without echo and signals for as long as it lives
// (Ctrl-C then arrives as a byte, read as quit), and restores it however the node ends.
class RawTerminal {
 public:
  explicit RawTerminal(int fd) : fd_(fd) {
    if (tcgetattr(fd_, &saved_) != 0) return;
    termios raw = saved_;
    raw.c_lflag &= ~static_cast<tcflag_t>(ICANON | ECHO | ISIG);
    raw.c_cc[VMIN] = 0;
    raw.c_cc[VTIME] = 0;
    active_ = tcsetattr(fd_, TCSANOW, &raw) == 0;
  }
  ~RawTerminal() {
    if (active_) tcsetattr(fd_, TCSANOW, &saved_);
  }
  RawTerminal(const RawTerminal&) = delete;
  RawTerminal& operator=(const RawTerminal&) = delete;
  bool active() const { return active_; }

 private:
  int fd_;
  termios saved_{};
  bool active_ = false;
};

// What one poll of the keyboard gave: bytes, nothing yet, or the end of the terminal.
enum class Read { kBytes, kNothing, kClosed };

Read readKeys(int fd, int timeout_ms, std::string* bytes) {
  pollfd p{fd, POLLIN, 0};
  const int ready = poll(&p, 1, timeout_ms);
  if (ready <= 0) return (ready < 0 && errno != EINTR) ? Read::kClosed : Read::kNothing;
  if (p.revents & (POLLHUP | POLLERR | POLLNVAL) && !(p.revents & POLLIN)) return Read::kClosed;
  char buffer[64];
  const ssize_t n = read(fd, buffer, sizeof buffer);
  if (n == 0) return Read::kClosed;  // end of file: the terminal is gone
  if (n < 0) return (errno == EINTR || errno == EAGAIN) ? Read::kNothing : Read::kClosed;
  bytes->assign(buffer, static_cast<std::size_t>(n));
  return Read::kBytes;
}

geometry_msgs::Twist twist(const Velocity& command) {
  geometry_msgs::Twist t;
  t.linear.x = command.v;
  t.angular.z = command.w;
  return t;
}

void show(const std::string& line) {
  std::printf("\r\033[K%s", line.c_str());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  if (roomba_rrt::nodes::printedHelp(argc, argv, "roomba_teleop",
                                     "Drives the Roomba from the keyboard: cmd_vel out, the "
                                     "bumper shown.")) {
    return 0;
  }
  ros::init(argc, argv, "roomba_teleop", ros::init_options::NoSigintHandler);
  ros::NodeHandle nh, pnh("~");
  roomba_rrt::nodes::NodeParams params(pnh);
  teleop::TeleopLimits limits;
  try {
    limits.max_linear_speed = params.get("max_linear_speed", limits.max_linear_speed);
    limits.max_angular_speed = params.get("max_angular_speed", limits.max_angular_speed);
    limits.linear_step = params.get("linear_step", limits.linear_step);
    limits.angular_step = params.get("angular_step", limits.angular_step);
    try {
      teleop::validate(limits);
    } catch (const roomba_rrt::util::InvalidInput& e) {
      throw std::invalid_argument(std::string("~") + e.what());
    }
  } catch (const std::invalid_argument& e) {
    ROS_FATAL("roomba_teleop: %s", e.what());
    return 1;
  }
  params.warnUnknown();
  if (!isatty(STDIN_FILENO)) {
    ROS_FATAL(
        "roomba_teleop reads the keyboard: run it in a terminal of its own (rosrun roomba_rrt "
        "roomba_teleop), not with its input redirected or from a launch file without a terminal");
    return 1;
  }

  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  std::signal(SIGHUP, onSignal);
  std::signal(SIGPIPE, SIG_IGN);

  ros::Publisher cmd_vel = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
  BumperState bumper;
  bool bumper_known = false;
  ros::Subscriber bumper_sub =
      nh.subscribe<roomba_rrt::Bumper>("bumper", 1, [&](const roomba_rrt::Bumper::ConstPtr& msg) {
        bumper = {static_cast<bool>(msg->pressed), static_cast<bool>(msg->left),
                  static_cast<bool>(msg->right)};
        bumper_known = true;
      });

  RawTerminal terminal(STDIN_FILENO);
  std::printf("%s\n", teleop::helpText(limits).c_str());
  std::printf("Publishing on %s, bumper from %s.\n", cmd_vel.getTopic().c_str(),
              bumper_sub.getTopic().c_str());

  teleop::KeyDecoder decoder;
  Velocity command;
  std::string shown, bytes;
  bool quit = false;
  while (!quit && !g_signalled && ros::ok()) {
    switch (readKeys(STDIN_FILENO, 100, &bytes)) {
      case Read::kClosed:
        quit = true;
        break;
      case Read::kNothing:
        break;
      case Read::kBytes:
        for (const teleop::Key key : decoder.feed(bytes)) {
          if (key == teleop::Key::kQuit) quit = true;
          command = teleop::applyKey(command, key, limits);
        }
        break;
    }
    if (quit) break;
    cmd_vel.publish(twist(command));
    ros::spinOnce();
    const std::string line = teleop::statusLine(command, bumper, bumper_known);
    if (line != shown) show(shown = line);
  }

  // Stop the robot whatever ended the loop; publish a few times so that a stop sent just after
  // a subscriber connected is not lost.
  for (int i = 0; i < 3 && ros::ok(); ++i) {
    cmd_vel.publish(twist(Velocity{}));
    ros::WallDuration(0.05).sleep();
  }
  std::printf("\nroomba_teleop: stopped the robot, bye.\n");
  ros::shutdown();
  return 0;
}
