// Plane geometry of the planning world: points, circular obstacles, the sampling box.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace roomba_rrt::planning {

/// A point (or vector) in the plane, metres.
struct Point2 {
  double x = 0;
  double y = 0;
};

/// A circular obstacle: the closed disc of `radius` around `center`.
struct Circle {
  Point2 center;
  double radius = 0;
};

/// The axis-aligned box in which random points are drawn (the lab: [0, 10] x [0, 10]).
struct Bounds {
  double x_min = 0;
  double x_max = 10;
  double y_min = 0;
  double y_max = 10;
};

inline double squaredDistance(const Point2& a, const Point2& b) {
  const double dx = a.x - b.x;
  const double dy = a.y - b.y;
  return dx * dx + dy * dy;
}

inline double distance(const Point2& a, const Point2& b) {
  return std::sqrt(squaredDistance(a, b));
}

inline bool contains(const Bounds& bounds, const Point2& p) {
  return p.x >= bounds.x_min && p.x <= bounds.x_max && p.y >= bounds.y_min && p.y <= bounds.y_max;
}

/// True when `p` lies in the closed disc (on the rim counts as a collision).
inline bool contains(const Circle& circle, const Point2& p) {
  return squaredDistance(p, circle.center) <= circle.radius * circle.radius;
}

/// True when the segment a-b has a point in the closed disc (exact segment-circle test:
/// the distance from the centre to the closest point of the segment is at most the radius).
/// Inline, as the other small tests here: the planner calls it for every obstacle on every step.
inline bool segmentMeetsCircle(const Point2& a, const Point2& b, const Circle& circle) {
  // Closest point of the segment to the centre: a + t (b - a), t clamped to [0, 1].
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double length_sq = dx * dx + dy * dy;
  double t = 0;
  if (length_sq > 0) {
    t = ((circle.center.x - a.x) * dx + (circle.center.y - a.y) * dy) / length_sq;
    t = std::clamp(t, 0.0, 1.0);
  }
  const Point2 closest{a.x + t * dx, a.y + t * dy};
  return contains(circle, closest);
}

/// Sum of the lengths of consecutive segments; 0 for fewer than two points.
double pathLength(const std::vector<Point2>& path);

}  // namespace roomba_rrt::planning
