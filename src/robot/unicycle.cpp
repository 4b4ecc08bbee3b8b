#include "roomba_rrt/robot/unicycle.h"

#include <algorithm>
#include <cmath>

namespace roomba_rrt::robot {

namespace {
double clampFinite(double value, double limit) {
  if (!std::isfinite(value)) return 0.0;
  return std::clamp(value, -limit, limit);
}
}  // namespace

Velocity clampCommand(const Velocity& cmd, double max_linear, double max_angular) {
  return {clampFinite(cmd.v, max_linear), clampFinite(cmd.w, max_angular)};
}

double wrapAngle(double theta) {
  if (theta > -M_PI && theta <= M_PI) return theta;    // the common case, exact
  double wrapped = std::remainder(theta, 2.0 * M_PI);  // [−π, π]
  return wrapped <= -M_PI ? wrapped + 2.0 * M_PI : wrapped;
}

Pose2D integrateArc(const Pose2D& pose, const Velocity& cmd, double dt) {
  const double half_turn = 0.5 * cmd.w * dt;
  const double mid_heading = pose.theta + half_turn;
  // Chord length of the arc: 2v/w·sin(wΔt/2), or vΔt on a straight line.
  const double chord =
      std::abs(cmd.w) < kStraightLineOmega ? cmd.v * dt : 2.0 * cmd.v / cmd.w * std::sin(half_turn);
  return {pose.x + chord * std::cos(mid_heading), pose.y + chord * std::sin(mid_heading),
          wrapAngle(pose.theta + cmd.w * dt)};
}

}  // namespace roomba_rrt::robot
