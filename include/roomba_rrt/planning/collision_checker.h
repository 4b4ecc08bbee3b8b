// Is a point, or a straight motion, free of the obstacles (circles, rectangles and a map's blocked
// cells, grown by the robot's radius and clearance)?
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "roomba_rrt/planning/geometry.h"
#include "roomba_rrt/planning/planner_options.h"
#include "roomba_rrt/planning/problem.h"

namespace roomba_rrt::planning {

/// Every member is inline: the planner asks it once or more per iteration.
///
/// The robot is a disc of radius `margin` (robot_radius + clearance; 0 = a point, the lab), so the
/// checker works in the grown world: a disc's radius grows by margin, and a rectangle becomes the
/// rounded rectangle of every point within margin of it (tested by the exact distance). The walls
/// are the planner's business: it samples in the bounds shrunk by margin (see shrink()). A map's
/// cells are asked of its ClearanceMap, for a disc of radius margin, exactly.
class CollisionChecker {
 public:
  CollisionChecker(std::vector<Circle> obstacles, CollisionCheck mode,
                   std::vector<Rectangle> rectangles = {}, double margin = 0,
                   std::shared_ptr<const geometry::ClearanceMap> map = nullptr)
      : obstacles_(std::move(obstacles)),
        rectangles_(std::move(rectangles)),
        margin_(margin),
        mode_(mode),
        map_(std::move(map)),
        disc_(map_ ? map_->disc(margin) : geometry::ClearanceMap::Disc{}) {
    for (Circle& c : obstacles_) c.radius += margin;  // + 0 leaves the lab's discs bit-identical
    // Each rectangle's box grown by margin, for the inline quick test of isSegmentFree().
    grown_boxes_.reserve(rectangles_.size());
    for (const Rectangle& r : rectangles_) {
      grown_boxes_.push_back(
          {r.min_x - margin, r.min_y - margin, r.max_x + margin, r.max_y + margin});
    }
    // Each disc's part of the quick test's reach (see isSegmentFree()), computed once.
    reach_.reserve(obstacles_.size());
    for (const Circle& c : obstacles_) {
      const double slack =
          1e-12 * (std::max(std::abs(c.center.x), std::abs(c.center.y)) + std::abs(c.radius));
      reach_.push_back(c.radius + slack);
    }
  }

  /// True when p is outside every (closed, grown) disc and rectangle.
  bool isFree(const Point2& p) const {
    for (const Circle& c : obstacles_) {
      if (contains(c, p)) return false;
    }
    for (const Rectangle& box : rectangles_) {
      if (geometry::withinMargin(box, p, margin_)) return false;
    }
    return !map_ || map_->discFree(p, disc_);
  }
  /// True when the whole segment a-b is outside every grown obstacle (exact segment tests).
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
      if (segmentMeets({a, b}, c)) return false;
    }
    for (std::size_t i = 0; i < rectangles_.size(); ++i) {
      // Quick test: the segment's bounding box misses the rectangle's grown box (the exact test's
      // own first test, inline), so only nearby rectangles cost a call.
      const Rectangle& g = grown_boxes_[i];
      if (std::max(a.x, b.x) < g.min_x || std::min(a.x, b.x) > g.max_x ||
          std::max(a.y, b.y) < g.min_y || std::min(a.y, b.y) > g.max_y) {
        continue;
      }
      if (segmentMeets({a, b}, rectangles_[i], margin_)) return false;
    }
    return !map_ || map_->sweepFree(a, b, disc_);
  }
  /// The planner's check of a new edge from a (already in the tree) to b, by mode:
  /// `points` checks only b against the discs and rectangles (the lab), `segments` the whole
  /// edge. A map is always checked along the whole edge: its walls are a cell thick, and a step
  /// would jump them.
  bool isMotionFree(const Point2& a, const Point2& b) const {
    if (mode_ == CollisionCheck::kSegments) return isSegmentFree(a, b);
    return isFree(b) && (!map_ || map_->sweepFree(a, b, disc_));
  }
  CollisionCheck mode() const { return mode_; }
  /// The discs, already grown by margin(); the rectangles as given (grown by margin() in tests).
  const std::vector<Circle>& obstacles() const { return obstacles_; }
  const std::vector<Rectangle>& rectangles() const { return rectangles_; }
  double margin() const { return margin_; }
  const geometry::ClearanceMap* map() const { return map_.get(); }

 private:
  std::vector<Circle> obstacles_;
  std::vector<Rectangle> rectangles_;
  std::vector<Rectangle> grown_boxes_;  ///< per rectangle: its bounding box grown by margin_
  double margin_;
  std::vector<double> reach_;  ///< per disc: its radius plus its share of the quick test's slack
  CollisionCheck mode_;
  std::shared_ptr<const geometry::ClearanceMap> map_;
  geometry::ClearanceMap::Disc disc_;  ///< the map's thresholds for a disc of radius margin_
};

/// The checker of `problem`'s obstacles and map grown by its robot_radius + clearance.
inline CollisionChecker collisionChecker(const Problem& problem, CollisionCheck mode) {
  return CollisionChecker(problem.obstacles, mode, problem.rectangles, robotMargin(problem),
                          problem.map);
}

}  // namespace roomba_rrt::planning
