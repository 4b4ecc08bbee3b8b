#include "roomba_rrt/navigation/path_checker.h"

#include <cmath>
#include <limits>
#include <utility>

namespace roomba_rrt::navigation {

using planning::Point2;

std::size_t nearestSegment(const Path& path, const Point2& p) {
  std::size_t nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double d =
        planning::distance(p, geometry::closestPoint(planning::Segment{path[i], path[i + 1]}, p));
    if (d < best) {
      best = d;
      nearest = i;
    }
  }
  return nearest;
}

PathChecker::PathChecker(planning::Problem world)
    : world_(std::move(world)),
      checker_(planning::collisionChecker(world_, planning::CollisionCheck::kSegments)),
      shrunk_(planning::shrink(world_.bounds, planning::robotMargin(world_))) {}

bool PathChecker::fits() const {
  return shrunk_.x_min < shrunk_.x_max && shrunk_.y_min < shrunk_.y_max;
}

bool PathChecker::isPointFree(const Point2& p) const {
  return planning::contains(shrunk_, p) && checker_.isFree(p);
}

bool PathChecker::isPathFree(const Path& path, std::size_t from) const {
  // A path planned from a start inside the grown obstacles begins with that start.
  if (from == 0 && path.size() > 1 && !isPointFree(path[0])) from = 1;
  for (std::size_t i = from; i < path.size(); ++i) {
    if (!isPointFree(path[i])) return false;
    if (i + 1 < path.size() && !checker_.isSegmentFree(path[i], path[i + 1])) return false;
  }
  return true;
}

Point2 PathChecker::freeStart(const Point2& start) const {
  if (isPointFree(start)) return start;
  for (int ring = 1; ring <= 25; ++ring) {
    const double r = 0.01 * ring;
    for (int k = 0; k < 32; ++k) {
      const double a = 2.0 * M_PI * k / 32;
      const Point2 p{start.x + r * std::cos(a), start.y + r * std::sin(a)};
      if (isPointFree(p)) return p;
    }
  }
  return start;
}

}  // namespace roomba_rrt::navigation
