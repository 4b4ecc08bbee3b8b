#include "roomba_rrt/sim/contact.h"

#include <algorithm>
#include <cmath>

namespace roomba_rrt::sim {

namespace {

/// Overlap below this (m) is floating-point rounding of a push-back, not penetration.
constexpr double kPenetrationTolerance = 1e-9;
/// A contact closer than this to the heading line (sin 10°) closes both bump switches.
const double kHeadOnLateral = std::sin(10.0 * M_PI / 180.0);
/// Enough for any corner: each pass removes the deepest overlaps, two usually suffice.
constexpr int kMaxResolvePasses = 8;

/// The point of a rectangle closest to (x, y) (the point itself when inside).
void closestPoint(const Rectangle& box, double x, double y, double& qx, double& qy) {
  qx = std::clamp(x, box.min_x, box.max_x);
  qy = std::clamp(y, box.min_y, box.max_y);
}

/// One pass over every surface; returns true when something was pushed.
bool pushOutOnce(const World& world, double& x, double& y) {
  const double r = world.robot_radius;
  bool pushed = false;
  // Walls: the normal is an axis, so pushing back is a clamp (exactly onto the wall).
  if (x < r || x > world.width - r) {
    x = std::clamp(x, r, world.width - r);
    pushed = true;
  }
  if (y < r || y > world.height - r) {
    y = std::clamp(y, r, world.height - r);
    pushed = true;
  }
  for (const Circle& c : world.circles) {
    const double dx = x - c.x, dy = y - c.y;
    const double reach = c.radius + r;
    const double d2 = dx * dx + dy * dy;
    if (d2 >= (reach - kPenetrationTolerance) * (reach - kPenetrationTolerance)) continue;
    const double d = std::sqrt(d2);
    if (d > 0) {
      x = c.x + dx * (reach / d);
      y = c.y + dy * (reach / d);
    } else {
      x = c.x - reach;  // exactly at the centre: no normal, leave towards −x
    }
    pushed = true;
  }
  for (const Rectangle& box : world.rectangles) {
    double qx, qy;
    closestPoint(box, x, y, qx, qy);
    const double dx = x - qx, dy = y - qy;
    const double d2 = dx * dx + dy * dy;
    if (d2 >= (r - kPenetrationTolerance) * (r - kPenetrationTolerance)) continue;
    if (d2 > 0) {  // centre outside: along the normal through the closest point
      const double d = std::sqrt(d2);
      x = qx + dx * (r / d);
      y = qy + dy * (r / d);
    } else {  // centre inside: out through the nearest side
      const double left = x - box.min_x, right = box.max_x - x;
      const double bottom = y - box.min_y, top = box.max_y - y;
      const double nearest = std::min({left, right, bottom, top});
      if (nearest == left) {
        x = box.min_x - r;
      } else if (nearest == right) {
        x = box.max_x + r;
      } else if (nearest == bottom) {
        y = box.min_y - r;
      } else {
        y = box.max_y + r;
      }
    }
    pushed = true;
  }
  return pushed;
}

}  // namespace

bool penetrates(const World& world, double x, double y) {
  const double r = world.robot_radius - kPenetrationTolerance;
  if (x < r || y < r || x > world.width - r || y > world.height - r) return true;
  for (const Circle& c : world.circles) {
    const double dx = x - c.x, dy = y - c.y, reach = c.radius + r;
    if (dx * dx + dy * dy < reach * reach) return true;
  }
  for (const Rectangle& box : world.rectangles) {
    double qx, qy;
    closestPoint(box, x, y, qx, qy);
    const double dx = x - qx, dy = y - qy;
    if (dx * dx + dy * dy < r * r) return true;
  }
  return false;
}

bool resolvePenetration(const World& world, double& x, double& y) {
  for (int pass = 0; pass < kMaxResolvePasses; ++pass) {
    if (!pushOutOnce(world, x, y)) return true;
  }
  return !penetrates(world, x, y);
}

BumperState senseBumper(const World& world, const Pose2D& pose) {
  const double r = world.robot_radius + kContactTolerance;
  BumperState bumper;
  double cos_t = 0, sin_t = 0;  // of the heading, computed on the first contact only
  // (nx, ny): direction from the robot's centre towards the contact, any length.
  auto contact = [&](double nx, double ny) {
    if (!bumper.pressed) {
      cos_t = std::cos(pose.theta);
      sin_t = std::sin(pose.theta);
    }
    const double norm = std::hypot(nx, ny);
    const double lateral = norm > 0 ? (-sin_t * nx + cos_t * ny) / norm : 0.0;  // sin(bearing)
    bumper.pressed = true;
    bumper.left = bumper.left || lateral >= -kHeadOnLateral;
    bumper.right = bumper.right || lateral <= kHeadOnLateral;
  };
  const double x = pose.x, y = pose.y;
  if (x <= r) contact(-1, 0);
  if (x >= world.width - r) contact(1, 0);
  if (y <= r) contact(0, -1);
  if (y >= world.height - r) contact(0, 1);
  for (const Circle& c : world.circles) {
    const double dx = c.x - x, dy = c.y - y, reach = c.radius + r;
    if (dx * dx + dy * dy <= reach * reach) contact(dx, dy);
  }
  for (const Rectangle& box : world.rectangles) {
    double qx, qy;
    closestPoint(box, x, y, qx, qy);
    const double dx = qx - x, dy = qy - y;
    if (dx * dx + dy * dy <= r * r) contact(dx, dy);
  }
  return bumper;
}

}  // namespace roomba_rrt::sim
