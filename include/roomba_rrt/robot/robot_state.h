// The robot's state as the simulation and the behaviours see it: pose, commanded velocity and
// bumper. Plain values, no ROS.
#pragma once

namespace roomba_rrt::robot {

/// A planar pose in the map frame (REP-103: metres, radians, x forward, y left, θ counter-clockwise
/// from +x).
struct Pose2D {
  double x = 0;
  double y = 0;
  double theta = 0;
};

/// A unicycle command: linear speed v along the heading (m/s, negative drives backwards) and
/// angular speed w (rad/s, positive turns left).
struct Velocity {
  double v = 0;
  double w = 0;
};

/// The Roomba's front bumper, recomputed from the geometry every step. Touching counts as pressed.
/// `left` and `right` are the two bump switches: a contact on the robot's +y side closes `left`,
/// on its −y side `right`, and a contact close to the heading line (head-on, or straight behind)
/// closes both.
struct BumperState {
  bool pressed = false;
  bool left = false;
  bool right = false;
};

}  // namespace roomba_rrt::robot
