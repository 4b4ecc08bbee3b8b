// Is a point, or a straight motion, free of the circular obstacles?
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "roomba_rrt/planning/geometry.h"
#include "roomba_rrt/planning/planner_options.h"

namespace roomba_rrt::planning {

/// Every member is inline: the planner asks it once or more per iteration.
class CollisionChecker {
 public:
  CollisionChecker(std::vector<Circle> obstacles, CollisionCheck mode)
      : obstacles_(std::move(obstacles)), mode_(mode) {}

  /// True when p is outside every (closed) disc.
  bool isFree(const Point2& p) const {
    for (const Circle& c : obstacles_) {
      if (contains(c, p)) return false;
    }
    return true;
  }
  /// True when the whole segment a-b is outside every disc (exact segment-circle test).
  bool isSegmentFree(const Point2& a, const Point2& b) const {
    // A quick test first, without the exact test's division: every point of the segment is
    // within its length L of a, so a disc farther than r + L from a cannot meet it. `slack`
    // (1e-12 of the coordinates' size) is far above the rounding of either test, so the quick
    // test never calls free what the exact test would call a collision: the answer is the same.
    const double length = distance(a, b);
    const double size = std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)});
    for (const Circle& c : obstacles_) {
      const double slack =
          1e-12 * (std::max({size, std::abs(c.center.x), std::abs(c.center.y)}) + c.radius);
      const double clear = c.radius + length + slack;
      if (squaredDistance(a, c.center) > clear * clear) continue;  // too far to touch the segment
      if (segmentMeetsCircle(a, b, c)) return false;
    }
    return true;
  }
  /// The planner's check of a new edge from a (already in the tree) to b, by mode:
  /// `points` checks only b (the lab), `segments` the whole edge.
  bool isMotionFree(const Point2& a, const Point2& b) const {
    return mode_ == CollisionCheck::kPoints ? isFree(b) : isSegmentFree(a, b);
  }
  CollisionCheck mode() const { return mode_; }
  const std::vector<Circle>& obstacles() const { return obstacles_; }

 private:
  std::vector<Circle> obstacles_;
  CollisionCheck mode_;
};

}  // namespace roomba_rrt::planning
