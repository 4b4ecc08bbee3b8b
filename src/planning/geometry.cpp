#include "roomba_rrt/planning/geometry.h"

#include <algorithm>

namespace roomba_rrt::planning {

bool segmentMeetsCircle(const Point2& a, const Point2& b, const Circle& circle) {
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

double pathLength(const std::vector<Point2>& path) {
  double length = 0;
  for (std::size_t i = 1; i < path.size(); ++i) length += distance(path[i - 1], path[i]);
  return length;
}

}  // namespace roomba_rrt::planning
