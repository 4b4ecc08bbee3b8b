#include "roomba_rrt/navigation/motion_guard.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "roomba_rrt/geometry/geometry.h"
#include "roomba_rrt/geometry/occupancy_grid.h"
#include "roomba_rrt/util/require.h"

namespace roomba_rrt::navigation {
namespace {

constexpr double kSampleSpacing = 0.005;  // m along the arc between two checked centres
constexpr int kBisections = 10;           // the safe fraction of v to about 1/1000

}  // namespace

MotionGuard::MotionGuard(planning::Problem world, double rate, double max_linear_accel,
                         double margin, int ticks)
    : world_(std::move(world)),
      dt_(1.0 / rate),
      max_linear_accel_(max_linear_accel),
      margin_(margin),
      ticks_(ticks) {
  util::requirePositive("rate", rate);
  util::requirePositive("max_linear_accel", max_linear_accel);
  util::require(std::isfinite(margin) && margin >= 0, "margin", "finite and >= 0", margin);
  util::require(ticks >= 1, "ticks", ">= 1", ticks);
  util::require(std::isfinite(world_.robot_radius) && world_.robot_radius >= 0, "robot_radius",
                "finite and >= 0", world_.robot_radius);
}

double MotionGuard::gap(double x, double y) const {
  const planning::Point2 p{x, y};
  const planning::Bounds& b = world_.bounds;
  double nearest = std::min({x - b.x_min, b.x_max - x, y - b.y_min, b.y_max - y});
  for (const auto& c : world_.obstacles) nearest = std::min(nearest, geometry::distance(c, p));
  for (const auto& r : world_.rectangles) nearest = std::min(nearest, geometry::distance(r, p));
  if (world_.map) {
    // Only gaps below margin_ matter (safe() compares the others with each other only when one is
    // below it), so the map's cells are searched that far: a few hundred at most, not the room.
    const double reach = std::min(nearest, world_.robot_radius + margin_ + 1e-3);
    nearest = std::min(nearest, geometry::distanceToBlocked(world_.map->grid(), p, reach,
                                                            world_.map->unknownIsFree()));
  }
  return nearest - world_.robot_radius;
}

bool MotionGuard::safe(const robot::Pose2D& pose, double v, double w) const {
  // The way the command would take the robot before it can stop: ticks_ at v, then braking.
  const double reach = std::fabs(v) * dt_ * ticks_ + v * v / (2.0 * max_linear_accel_);
  const int samples = std::max(1, static_cast<int>(std::ceil(reach / kSampleSpacing)));
  const double start_gap = gap(pose.x, pose.y);
  const double curvature = std::fabs(v) > 1e-12 ? w / v : 0.0;  // the arc's, signed by v
  const double direction = v < 0 ? -1.0 : 1.0;
  for (int i = 1; i <= samples; ++i) {
    const double s = reach * i / samples;  // arc length from the pose
    const double heading = pose.theta + direction * curvature * s;
    double x, y;
    if (std::fabs(curvature) < 1e-9) {
      x = pose.x + direction * s * std::cos(pose.theta);
      y = pose.y + direction * s * std::sin(pose.theta);
    } else {
      x = pose.x + (std::sin(heading) - std::sin(pose.theta)) / curvature;
      y = pose.y - (std::cos(heading) - std::cos(pose.theta)) / curvature;
    }
    const double g = gap(x, y);
    if (g < margin_ && g < start_gap - 1e-9) return false;  // closer, and too close
  }
  return true;
}

robot::Velocity MotionGuard::filter(const robot::Pose2D& pose, const robot::Velocity& cmd) const {
  if (cmd.v == 0 || safe(pose, cmd.v, cmd.w)) return cmd;
  double lo = 0, hi = 1;  // fractions of v: lo is safe, hi is not
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    (safe(pose, mid * cmd.v, cmd.w) ? lo : hi) = mid;
  }
  return {lo * cmd.v, cmd.w};
}

}  // namespace roomba_rrt::navigation
