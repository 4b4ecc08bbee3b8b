#include "roomba_rrt/geometry/geometry.h"

namespace roomba_rrt::geometry {

bool segmentIntersects(const Segment& s, const Rectangle& box) {
  // Clip the parameter range [0, 1] of a + t (b - a) against the four slabs of the box.
  double t0 = 0, t1 = 1;
  const double d[2] = {s.b.x - s.a.x, s.b.y - s.a.y};
  const double a[2] = {s.a.x, s.a.y};
  const double lo[2] = {box.min_x, box.min_y};
  const double hi[2] = {box.max_x, box.max_y};
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0) {
      if (a[axis] < lo[axis] || a[axis] > hi[axis]) return false;  // parallel and outside
      continue;
    }
    double enter = (lo[axis] - a[axis]) / d[axis];
    double leave = (hi[axis] - a[axis]) / d[axis];
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter);
    t1 = std::min(t1, leave);
    if (t0 > t1) return false;
  }
  return true;
}

namespace {

// Squared distance between a rectangle and a segment that does not cross it. Two disjoint convex
// polygons are closest at a vertex of one of them: an end of the segment against the rectangle,
// or a corner of the rectangle against the segment.
double squaredDistanceApart(const Rectangle& box, const Segment& s) {
  double d2 = std::min(squaredDistance(box, s.a), squaredDistance(box, s.b));
  for (const Point2 corner : {Point2{box.min_x, box.min_y}, Point2{box.max_x, box.min_y},
                              Point2{box.max_x, box.max_y}, Point2{box.min_x, box.max_y}}) {
    d2 = std::min(d2, squaredDistance(corner, closestPoint(s, corner)));
  }
  return d2;
}

}  // namespace

double distance(const Rectangle& box, const Segment& s) {
  return segmentIntersects(s, box) ? 0.0 : std::sqrt(squaredDistanceApart(box, s));
}

bool segmentMeets(const Segment& s, const Rectangle& box, double margin) {
  // Quick rejection: the segment's bounding box against the rectangle's grown by margin.
  if (std::max(s.a.x, s.b.x) < box.min_x - margin || std::min(s.a.x, s.b.x) > box.max_x + margin ||
      std::max(s.a.y, s.b.y) < box.min_y - margin || std::min(s.a.y, s.b.y) > box.max_y + margin) {
    return false;
  }
  if (segmentIntersects(s, box)) return true;
  return margin > 0 && squaredDistanceApart(box, s) <= margin * margin;
}

double pathLength(const std::vector<Point2>& path) {
  double length = 0;
  for (std::size_t i = 1; i < path.size(); ++i) length += distance(path[i - 1], path[i]);
  return length;
}

}  // namespace roomba_rrt::geometry
