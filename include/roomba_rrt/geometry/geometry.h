// Plane geometry shared by the simulator (contact, bumper) and the planner (collision checks):
// points, circles, axis-aligned rectangles and segments; closest points, distances, point-inside
// tests and exact segment tests. ROS-free; the small tests are inline (they run in inner loops).
//
// Every "meets" test takes a margin m >= 0: it asks whether the shape grown by m (a circle's
// radius + m; a rectangle becomes a rounded rectangle, every point within m of it) has a point in
// common with the segment. The boundary counts as a hit (closed shapes).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace roomba_rrt::geometry {

/// A point (or vector) in the plane, metres.
struct Point2 {
  double x = 0;
  double y = 0;
};

/// The closed disc of `radius` around `center` (a table leg, a lab obstacle).
struct Circle {
  Point2 center;
  double radius = 0;
};

/// A closed axis-aligned rectangle (a sofa, a cupboard); keys as in the world file.
struct Rectangle {
  double min_x = 0;
  double min_y = 0;
  double max_x = 0;
  double max_y = 0;
};

/// The straight segment from a to b (a motion of the robot's centre).
struct Segment {
  Point2 a;
  Point2 b;
};

inline double squaredDistance(const Point2& a, const Point2& b) {
  const double dx = a.x - b.x;
  const double dy = a.y - b.y;
  return dx * dx + dy * dy;
}

inline double distance(const Point2& a, const Point2& b) {
  return std::sqrt(squaredDistance(a, b));
}

/// True when `p` lies in the closed disc (on the rim counts).
inline bool contains(const Circle& circle, const Point2& p) {
  return squaredDistance(p, circle.center) <= circle.radius * circle.radius;
}

/// True when `p` lies in the closed rectangle (on the border counts).
inline bool contains(const Rectangle& box, const Point2& p) {
  return p.x >= box.min_x && p.x <= box.max_x && p.y >= box.min_y && p.y <= box.max_y;
}

/// The point of the rectangle closest to `p` (p itself when inside).
inline Point2 closestPoint(const Rectangle& box, const Point2& p) {
  return {std::clamp(p.x, box.min_x, box.max_x), std::clamp(p.y, box.min_y, box.max_y)};
}

/// The point of the segment closest to `p`: a + t (b - a), t clamped to [0, 1].
inline Point2 closestPoint(const Segment& s, const Point2& p) {
  const double dx = s.b.x - s.a.x;
  const double dy = s.b.y - s.a.y;
  const double length_sq = dx * dx + dy * dy;
  double t = 0;
  if (length_sq > 0) {
    t = ((p.x - s.a.x) * dx + (p.y - s.a.y) * dy) / length_sq;
    t = std::clamp(t, 0.0, 1.0);
  }
  return {s.a.x + t * dx, s.a.y + t * dy};
}

/// Squared distance from `p` to the rectangle (0 inside).
inline double squaredDistance(const Rectangle& box, const Point2& p) {
  return squaredDistance(p, closestPoint(box, p));
}

/// Distance from `p` to the rectangle (0 inside) and to the disc (0 inside).
inline double distance(const Rectangle& box, const Point2& p) {
  return std::sqrt(squaredDistance(box, p));
}
inline double distance(const Circle& circle, const Point2& p) {
  return std::max(0.0, distance(p, circle.center) - circle.radius);
}

/// True when `p` is within `margin` of the disc (in the disc grown by margin).
inline bool withinMargin(const Circle& circle, const Point2& p, double margin) {
  const double reach = circle.radius + margin;
  return squaredDistance(p, circle.center) <= reach * reach;
}

/// True when `p` is within `margin` of the rectangle (in the rounded rectangle grown by margin).
inline bool withinMargin(const Rectangle& box, const Point2& p, double margin) {
  return squaredDistance(box, p) <= margin * margin;
}

/// True when the segment has a point within `margin` of the disc (exact: the distance from the
/// centre to the segment's closest point is at most radius + margin).
inline bool segmentMeets(const Segment& s, const Circle& circle, double margin = 0) {
  return withinMargin(circle, closestPoint(s, circle.center), margin);
}

/// True when the segment crosses or touches the rectangle itself (Liang-Barsky clipping).
bool segmentIntersects(const Segment& s, const Rectangle& box);

/// Distance between the segment and the rectangle (0 when they meet).
double distance(const Rectangle& box, const Segment& s);

/// True when the segment has a point within `margin` of the rectangle (exact distance, not a
/// bounding box: near a corner the grown rectangle is round).
bool segmentMeets(const Segment& s, const Rectangle& box, double margin = 0);

/// Sum of the lengths of consecutive segments; 0 for fewer than two points.
double pathLength(const std::vector<Point2>& path);

}  // namespace roomba_rrt::geometry
