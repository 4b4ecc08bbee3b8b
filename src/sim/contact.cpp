#include "roomba_rrt/sim/contact.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace roomba_rrt::sim {

namespace {

using world::kPenetrationTolerance;
/// A contact closer than this to the heading line (sin 10°) closes both bump switches.
const double kHeadOnLateral = std::sin(10.0 * M_PI / 180.0);
/// Enough for any corner: each pass removes the deepest overlaps, two usually suffice.
constexpr int kMaxResolvePasses = 8;

/// Pushes the disc of radius r at (x, y) out of the rectangle along the normal through the
/// rectangle's closest point (out through the nearest side when the centre is inside); returns
/// true when it overlapped by more than the tolerance.
bool pushOutOf(const geometry::Rectangle& box, const double r, double& x, double& y) {
  const geometry::Point2 q = geometry::closestPoint(box, geometry::Point2{x, y});
  const double dx = x - q.x, dy = y - q.y;
  const double d2 = geometry::squaredDistance(geometry::Point2{x, y}, q);
  if (d2 >= (r - kPenetrationTolerance) * (r - kPenetrationTolerance)) return false;
  if (d2 > 0) {  // centre outside: along the normal through the closest point
    const double d = std::sqrt(d2);
    x = q.x + dx * (r / d);
    y = q.y + dy * (r / d);
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
  return true;
}

/// Pushes the disc out of the map's blocked cells near it, the deepest first: the disc pushed
/// straight off a wall's face is then clear of the neighbouring cells' corners along that face,
/// so a wall made of many squares acts like one flat wall (no sideways nudge at the seams).
bool pushOutOfMap(const geometry::OccupancyGrid& map, const double r, double& x, double& y) {
  thread_local std::vector<geometry::Rectangle> squares;
  geometry::blockedSquaresNear(map, geometry::Point2{x, y}, r, squares);
  if (squares.empty()) return false;
  const geometry::Point2 p{x, y};
  std::sort(squares.begin(), squares.end(),
            [&p](const geometry::Rectangle& a, const geometry::Rectangle& b) {
              return geometry::squaredDistance(a, p) < geometry::squaredDistance(b, p);
            });
  bool pushed = false;
  for (const geometry::Rectangle& square : squares) pushed = pushOutOf(square, r, x, y) || pushed;
  return pushed;
}

/// One pass over every surface; returns true when something was pushed.
bool pushOutOnce(const world::World& world, const double r, double& x, double& y) {
  bool pushed = false;
  // Walls: the normal is an axis, so pushing back is a clamp (exactly onto the wall).
  const double x0 = world.room.origin.x, y0 = world.room.origin.y;
  if (x < x0 + r || x > x0 + world.room.width - r) {
    x = std::clamp(x, x0 + r, x0 + world.room.width - r);
    pushed = true;
  }
  if (y < y0 + r || y > y0 + world.room.height - r) {
    y = std::clamp(y, y0 + r, y0 + world.room.height - r);
    pushed = true;
  }
  for (const geometry::Circle& c : world.room.circles) {
    const double dx = x - c.center.x, dy = y - c.center.y;
    const double reach = c.radius + r;
    const double d2 = geometry::squaredDistance(geometry::Point2{x, y}, c.center);
    if (d2 >= (reach - kPenetrationTolerance) * (reach - kPenetrationTolerance)) continue;
    const double d = std::sqrt(d2);
    if (d > 0) {
      x = c.center.x + dx * (reach / d);
      y = c.center.y + dy * (reach / d);
    } else {
      x = c.center.x - reach;  // exactly at the centre: no normal, leave towards −x
    }
    pushed = true;
  }
  for (const geometry::Rectangle& box : world.room.rectangles)
    pushed = pushOutOf(box, r, x, y) || pushed;
  if (world.room.map) pushed = pushOutOfMap(*world.room.map, r, x, y) || pushed;
  return pushed;
}

/// Closes the switches for a contact in direction (nx, ny) from a robot heading (cos_t, sin_t).
inline void closeSwitches(robot::BumperState& bumper, double cos_t, double sin_t, double nx,
                          double ny) {
  const double norm = std::hypot(nx, ny);
  const double lateral = norm > 0 ? (-sin_t * nx + cos_t * ny) / norm : 0.0;  // sin(bearing)
  bumper.pressed = true;
  bumper.left = bumper.left || lateral >= -kHeadOnLateral;
  bumper.right = bumper.right || lateral <= kHeadOnLateral;
}

// The public functions call these from inside the library, where they can be inlined (the
// library is shared: a call to an exported function would go through the PLT; world::penetrates
// is inline in world.h).
bool resolveDisc(const world::World& world, const double radius, double& x, double& y) {
  for (int pass = 0; pass < kMaxResolvePasses; ++pass) {
    if (!pushOutOnce(world, radius, x, y)) return true;
  }
  return !world::penetrates(world, radius, x, y);
}

robot::BumperState senseDisc(const world::World& world, const double radius,
                             const robot::Pose2D& pose) {
  const double r = radius + kContactTolerance;
  robot::BumperState bumper;
  double cos_t = 0, sin_t = 0;  // of the heading, computed on the first contact only
  // (nx, ny): direction from the robot's centre towards the contact, any length.
  auto contact = [&](double nx, double ny) {
    if (!bumper.pressed) {
      cos_t = std::cos(pose.theta);
      sin_t = std::sin(pose.theta);
    }
    closeSwitches(bumper, cos_t, sin_t, nx, ny);
  };
  const double x = pose.x, y = pose.y;
  const double x0 = world.room.origin.x, y0 = world.room.origin.y;
  if (x <= x0 + r) contact(-1, 0);
  if (x >= x0 + world.room.width - r) contact(1, 0);
  if (y <= y0 + r) contact(0, -1);
  if (y >= y0 + world.room.height - r) contact(0, 1);
  const geometry::Point2 p{x, y};
  for (const geometry::Circle& c : world.room.circles) {
    if (geometry::withinMargin(c, p, r)) contact(c.center.x - x, c.center.y - y);
  }
  for (const geometry::Rectangle& box : world.room.rectangles) {
    const geometry::Point2 q = geometry::closestPoint(box, p);
    if (geometry::withinMargin(box, p, r)) contact(q.x - x, q.y - y);
  }
  if (world.room.map) {
    thread_local std::vector<geometry::Rectangle> squares;
    geometry::blockedSquaresNear(*world.room.map, p, r, squares);
    for (const geometry::Rectangle& square : squares) {
      const geometry::Point2 q = geometry::closestPoint(square, p);
      contact(q.x - x, q.y - y);
    }
  }
  return bumper;
}

}  // namespace

bool resolvePenetration(const world::World& world, double& x, double& y) {
  return resolveDisc(world, world.robot().radius, x, y);
}

robot::BumperState senseBumper(const world::World& world, const robot::Pose2D& pose) {
  return senseDisc(world, world.robot().radius, pose);
}

bool resolvePenetration(const world::World& world, double radius, double& x, double& y) {
  return resolveDisc(world, radius, x, y);
}

robot::BumperState senseBumper(const world::World& world, double radius,
                               const robot::Pose2D& pose) {
  return senseDisc(world, radius, pose);
}

void pressBumper(robot::BumperState& bumper, const robot::Pose2D& pose, double nx, double ny) {
  closeSwitches(bumper, std::cos(pose.theta), std::sin(pose.theta), nx, ny);
}

}  // namespace roomba_rrt::sim
