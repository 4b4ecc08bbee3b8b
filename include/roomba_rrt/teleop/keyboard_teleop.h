// Driving the Roomba from a keyboard: keys in, a unicycle command out. No ROS and no terminal here:
// the roomba_teleop node reads the terminal and publishes; this file decides what a key means.
//
// The command is sticky, as on a gamepad's trim: each press of forward/backward changes the
// linear speed by one step, each press of left/right the angular speed, and the robot keeps the
// command until the next key. Space stops both at once. A terminal reports key presses, never
// releases, so "drive while held" cannot be done reliably over ssh; a command that stays until
// it is changed, shown on screen, can.
#pragma once

#include <string>
#include <vector>

#include "roomba_rrt/robot/robot_state.h"

namespace roomba_rrt::teleop {

enum class Key {
  kForward,   ///< w, W or the up arrow: one step faster forwards (or slower backwards)
  kBackward,  ///< s, S or the down arrow
  kLeft,      ///< a, A or the left arrow: one step more counter-clockwise
  kRight,     ///< d, D or the right arrow
  kStop,      ///< space, x or X: v = w = 0
  kQuit,      ///< q, Q, Ctrl-C or Ctrl-D
};

/// Turns the bytes a terminal in non-canonical mode sends into keys. Arrow keys arrive as the
/// three-byte escape sequences ESC [ A … ESC [ D (or ESC O A … in application cursor mode), which
/// one read() may split; the decoder keeps an unfinished sequence until the next feed. Bytes that
/// are no key (other letters, other escape sequences) are dropped.
class KeyDecoder {
 public:
  std::vector<Key> feed(const std::string& bytes);

 private:
  std::string pending_;  // the start of an escape sequence not yet complete
};

/// How far one press moves the command and where it stops (the robot's limits).
struct TeleopLimits {
  double max_linear_speed = 1.0;   ///< m/s, |v| never exceeds it (roomba_sim's default limit)
  double max_angular_speed = 2.0;  ///< rad/s, |w| never exceeds it
  double linear_step = 0.1;        ///< m/s per press
  double angular_step = 0.25;      ///< rad/s per press
};

/// Throws InvalidInput naming the field unless every value is finite and positive and each step
/// is at most its limit.
void validate(const TeleopLimits& limits);

/// The command after one key press (kQuit leaves it unchanged: quitting is the caller's job, and
/// it stops the robot). A press moves its speed to the next whole number of steps, so that as many
/// presses back return to exactly zero, clamped to the limits; the other speed is kept.
robot::Velocity applyKey(const robot::Velocity& command, Key key, const TeleopLimits& limits);

/// The one-line status the node redraws: the command and the bumper, e.g.
/// "v +0.30 m/s  w -0.50 rad/s  bumper: left".
std::string statusLine(const robot::Velocity& command, const robot::BumperState& bumper,
                       bool bumper_known);

/// The help printed once at start.
std::string helpText(const TeleopLimits& limits);

}  // namespace roomba_rrt::teleop
