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
      : obstacles_(std::move(obstacles)), mode_(mode) {
    // Each disc's part of the quick test's reach (see isSegmentFree()), computed once.
    reach_.reserve(obstacles_.size());
    for (const Circle& c : obstacles_) {
      const double slack =
          1e-12 * (std::max(std::abs(c.center.x), std::abs(c.center.y)) + std::abs(c.radius));
      reach_.push_back(c.radius + slack);
    }
  }

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
    // within its length L of a, so a disc farther than r + L from a cannot meet it. L is taken
    // as |dx| + |dy| (never less, and no square root), and a slack of 1e-12 of the coordinates'
    // and the radius's size is added, far above the rounding of either test, so the quick test
    // never calls free what the exact test would call a collision: the answer is the same.
    const double length = std::abs(b.x - a.x) + std::abs(b.y - a.y);
    const double size = std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)});
    const double segment_reach = length + 1e-12 * size;
    for (std::size_t i = 0; i < obstacles_.size(); ++i) {
      const Circle& c = obstacles_[i];
      const double clear = reach_[i] + segment_reach;
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
  std::vector<double> reach_;  ///< per disc: its radius plus its share of the quick test's slack
  CollisionCheck mode_;
};

}  // namespace roomba_rrt::planning
