// Uniform samples of the free space by bounded rejection sampling.
#pragma once

#include <optional>

#include "roomba_rrt/planning/collision_checker.h"
#include "roomba_rrt/planning/geometry.h"
#include "roomba_rrt/planning/plan_random.h"

namespace roomba_rrt::planning {

/// Draws a point uniformly and repeats while it is not free — at most `max_tries` times, so a
/// world without free room ends in std::nullopt instead of a hang. Without a map (the lab, the
/// furnished room) the point is x, then y, uniform in the bounds (the lab's order: two rand() per
/// try). On a map whose free tiles (geometry::FreeTiles) cover at most half the bounds' area, the
/// point is drawn in a random free tile instead: uniform over the same free points, with fewer
/// draws wasted on unknown border and walls (turtlebot3_world: 6 % of the rectangle). A tile
/// draw costs a third rand() and a read of the tile list, so on maps that are mostly floor the
/// rectangle stays (measured: warehouse's tiles, 88 % of its rectangle, were slower).
class FreeSpaceSampler {
 public:
  FreeSpaceSampler(const Bounds& bounds, const CollisionChecker& checker, int max_tries)
      : bounds_(bounds), checker_(checker), max_tries_(max_tries) {
    const geometry::ClearanceMap* map = checker.map();
    const double bounds_area = (bounds.x_max - bounds.x_min) * (bounds.y_max - bounds.y_min);
    if (map != nullptr && !map->freeTiles().empty() && 2 * map->freeTiles().area() <= bounds_area) {
      tiles_ = &map->freeTiles();
    }
  }

  /// `Random`: PlanRandom, MatlabRandom or FastRandom (anything with uniform() and uniform(lo,
  /// hi)).
  template <typename Random>
  std::optional<Point2> sample(Random& random) const {
    for (int attempt = 0; attempt < max_tries_; ++attempt) {
      if (tiles_) {
        // A tile may stick out of the bounds (a request's bounds smaller than the map).
        const Point2 p = tilePoint(random);
        if (contains(bounds_, p) && checker_.isFree(p)) return p;
      } else {
        const Point2 p = boundsPoint(random);
        if (checker_.isFree(p)) return p;
      }
    }
    return std::nullopt;
  }
  int maxTries() const { return max_tries_; }

 private:
  template <typename Random>
  Point2 boundsPoint(Random& random) const {
    // The lab's order: x first, then y, each from its own rand().
    const double x = random.uniform(bounds_.x_min, bounds_.x_max);
    const double y = random.uniform(bounds_.y_min, bounds_.y_max);
    return {x, y};
  }
  /// A point of a random free tile: the tile, then x, then y within it.
  template <typename Random>
  Point2 tilePoint(Random& random) const {
    const double t = random.uniform(), u = random.uniform(), v = random.uniform();
    return tiles_->point(t, u, v);
  }

  Bounds bounds_;
  const CollisionChecker& checker_;
  int max_tries_;
  const geometry::FreeTiles* tiles_ = nullptr;  ///< draw from these when set
};

}  // namespace roomba_rrt::planning
