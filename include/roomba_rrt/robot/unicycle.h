// The unicycle (differential-drive) model of the robot: speed clamp and exact arc integration.
// The simulator moves the robot with it; navigation predicts the robot's pose with it.
#pragma once

#include "roomba_rrt/robot/robot_state.h"

namespace roomba_rrt::robot {

/// Limits |v| to max_linear and |w| to max_angular, keeping the signs (the lab's clamp: the
/// spiral's first tick asks for 0.5 / 0.2 = 2.5 rad/s and gets 2.0). A NaN or infinite component
/// becomes 0, so a bad command stops the robot instead of poisoning its state.
Velocity clampCommand(const Velocity& cmd, double max_linear, double max_angular);

/// Below this |w| (rad/s) the arc is integrated as a straight line, as in the lab.
constexpr double kStraightLineOmega = 1e-3;

/// Moves `pose` along the exact arc driven by constant (v, w) for dt seconds:
///   x += 2v/w · cos(θ + wΔt/2) · sin(wΔt/2),  y += 2v/w · sin(θ + wΔt/2) · sin(wΔt/2),
///   and for |w| < 1e-3 the straight-line limit x += vΔt · cos(θ + wΔt/2) (same for y);
///   θ += wΔt, wrapped to (−π, π].
Pose2D integrateArc(const Pose2D& pose, const Velocity& cmd, double dt);

/// θ wrapped to (−π, π].
double wrapAngle(double theta);

}  // namespace roomba_rrt::robot
