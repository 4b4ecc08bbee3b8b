// Uniform samples of the free space by bounded rejection sampling.
#pragma once

#include <optional>

#include "roomba_rrt/planning/collision_checker.h"
#include "roomba_rrt/planning/geometry.h"
#include "roomba_rrt/planning/lab/matlab_random.h"

namespace roomba_rrt::planning {

/// Draws x, then y, uniformly in the bounds (the lab's order: two rand() per try) and repeats
/// while the point is inside an obstacle — at most `max_tries` times, so a world without free
/// room ends in std::nullopt instead of a hang.
class FreeSpaceSampler {
 public:
  FreeSpaceSampler(const Bounds& bounds, const CollisionChecker& checker, int max_tries)
      : bounds_(bounds), checker_(checker), max_tries_(max_tries) {}

  std::optional<Point2> sample(MatlabRandom& random) const {
    for (int attempt = 0; attempt < max_tries_; ++attempt) {
      // The lab's order: x first, then y, each from its own rand().
      const double x = random.uniform(bounds_.x_min, bounds_.x_max);
      const double y = random.uniform(bounds_.y_min, bounds_.y_max);
      if (checker_.isFree({x, y})) return Point2{x, y};
    }
    return std::nullopt;
  }
  int maxTries() const { return max_tries_; }

 private:
  Bounds bounds_;
  const CollisionChecker& checker_;
  int max_tries_;
};

}  // namespace roomba_rrt::planning
