// Keys to commands for roomba_teleop (see keyboard_teleop.h).
#include "roomba_rrt/teleop/keyboard_teleop.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "roomba_rrt/util/require.h"

namespace roomba_rrt::teleop {
namespace {

constexpr char kEscape = '\x1b';
constexpr char kCtrlC = '\x03';
constexpr char kCtrlD = '\x04';

// The key a single byte means, if any.
bool plainKey(char byte, Key* key) {
  switch (byte) {
    case 'w':
    case 'W':
      *key = Key::kForward;
      return true;
    case 's':
    case 'S':
      *key = Key::kBackward;
      return true;
    case 'a':
    case 'A':
      *key = Key::kLeft;
      return true;
    case 'd':
    case 'D':
      *key = Key::kRight;
      return true;
    case ' ':
    case 'x':
    case 'X':
      *key = Key::kStop;
      return true;
    case 'q':
    case 'Q':
    case kCtrlC:
    case kCtrlD:
      *key = Key::kQuit;
      return true;
    default:
      return false;
  }
}

// The key an arrow's final byte means (ESC [ A is up, B down, C right, D left).
bool arrowKey(char byte, Key* key) {
  switch (byte) {
    case 'A':
      *key = Key::kForward;
      return true;
    case 'B':
      *key = Key::kBackward;
      return true;
    case 'C':
      *key = Key::kRight;
      return true;
    case 'D':
      *key = Key::kLeft;
      return true;
    default:
      return false;
  }
}

// A speed one press away from `value` (presses = +1 or -1): the next whole number of steps in
// that direction, within ±limit. A value between two steps (a limit that is no multiple of the
// step) goes to the nearer step on the pressed side.
double stepped(double value, int presses, double step, double limit) {
  double steps = value / step;
  if (std::abs(steps - std::round(steps)) < 1e-6) steps = std::round(steps);
  const double next = presses > 0 ? std::floor(steps) + 1 : std::ceil(steps) - 1;
  return std::clamp(next * step, -limit, limit);
}

using util::requirePositive;

}  // namespace

std::vector<Key> KeyDecoder::feed(const std::string& bytes) {
  std::vector<Key> keys;
  for (const char byte : bytes) {
    Key key;
    if (!pending_.empty()) {
      pending_ += byte;
      if (pending_.size() == 2) {
        // ESC followed by '[' or 'O' starts a cursor key; any other byte after a lone ESC (the
        // Escape key itself) is read as typed.
        if (byte == '[' || byte == 'O') continue;
        pending_.clear();
        if (plainKey(byte, &key)) keys.push_back(key);
        continue;
      }
      // ESC [ <final>: keep parameter bytes (digits, ';') of longer sequences such as ESC [ 1 ; 5
      // A.
      if ((byte >= '0' && byte <= '9') || byte == ';') continue;
      if (arrowKey(byte, &key)) keys.push_back(key);
      pending_.clear();
    } else if (byte == kEscape) {
      pending_.assign(1, byte);
    } else if (plainKey(byte, &key)) {
      keys.push_back(key);
    }
  }
  return keys;
}

void validate(const TeleopLimits& limits) {
  requirePositive("max_linear_speed", limits.max_linear_speed);
  requirePositive("max_angular_speed", limits.max_angular_speed);
  requirePositive("linear_step", limits.linear_step);
  requirePositive("angular_step", limits.angular_step);
  if (limits.linear_step > limits.max_linear_speed) {
    throw util::InvalidInput("linear_step", "must be at most max_linear_speed (" +
                                                util::show(limits.max_linear_speed) + "), got " +
                                                util::show(limits.linear_step));
  }
  if (limits.angular_step > limits.max_angular_speed) {
    throw util::InvalidInput("angular_step", "must be at most max_angular_speed (" +
                                                 util::show(limits.max_angular_speed) + "), got " +
                                                 util::show(limits.angular_step));
  }
}

robot::Velocity applyKey(const robot::Velocity& command, Key key, const TeleopLimits& limits) {
  const auto linear = [&](int press) {
    return stepped(command.v, press, limits.linear_step, limits.max_linear_speed);
  };
  const auto angular = [&](int press) {
    return stepped(command.w, press, limits.angular_step, limits.max_angular_speed);
  };
  switch (key) {
    case Key::kForward:
      return {linear(+1), command.w};
    case Key::kBackward:
      return {linear(-1), command.w};
    case Key::kLeft:
      return {command.v, angular(+1)};
    case Key::kRight:
      return {command.v, angular(-1)};
    case Key::kStop:
      return {0, 0};
    case Key::kQuit:
      return command;
  }
  return command;
}

std::string statusLine(const robot::Velocity& command, const robot::BumperState& bumper,
                       bool bumper_known) {
  const char* contact = !bumper_known                 ? "no bumper message yet"
                        : !bumper.pressed             ? "free"
                        : bumper.left && bumper.right ? "pressed (both)"
                        : bumper.left                 ? "pressed (left)"
                                                      : "pressed (right)";
  char line[96];
  // +0.0 prints as "+0.00", never "-0.00": the sum with 0.0 turns a negative zero positive.
  std::snprintf(line, sizeof line, "v %+.2f m/s  w %+.2f rad/s  bumper: %s", command.v + 0.0,
                command.w + 0.0, contact);
  return line;
}

std::string helpText(const TeleopLimits& limits) {
  char text[512];
  std::snprintf(text, sizeof text,
                "Drive the Roomba (the command stays until you change it):\n"
                "  w / up arrow      faster forwards   (%.2f m/s per press, at most %.2f)\n"
                "  s / down arrow    faster backwards\n"
                "  a / left arrow    turn left          (%.2f rad/s per press, at most %.2f)\n"
                "  d / right arrow   turn right\n"
                "  space / x         stop\n"
                "  q / Ctrl-C        stop the robot and quit\n",
                limits.linear_step, limits.max_linear_speed, limits.angular_step,
                limits.max_angular_speed);
  return text;
}

}  // namespace roomba_rrt::teleop
