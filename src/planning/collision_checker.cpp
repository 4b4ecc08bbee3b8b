#include "roomba_rrt/planning/collision_checker.h"

namespace roomba_rrt::planning {

bool CollisionChecker::isFree(const Point2& p) const {
  for (const Circle& c : obstacles_) {
    if (contains(c, p)) return false;
  }
  return true;
}

bool CollisionChecker::isSegmentFree(const Point2& a, const Point2& b) const {
  for (const Circle& c : obstacles_) {
    if (segmentMeetsCircle(a, b, c)) return false;
  }
  return true;
}

}  // namespace roomba_rrt::planning
