// Is a point, or a straight motion, free of the circular obstacles?
#pragma once

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
    for (const Circle& c : obstacles_) {
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
