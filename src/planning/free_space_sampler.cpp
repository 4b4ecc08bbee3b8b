#include "roomba_rrt/planning/free_space_sampler.h"

namespace roomba_rrt::planning {

std::optional<Point2> FreeSpaceSampler::sample(MatlabRandom& random) const {
  for (int attempt = 0; attempt < max_tries_; ++attempt) {
    // The lab's order: x first, then y, each from its own rand().
    const double x = random.uniform(bounds_.x_min, bounds_.x_max);
    const double y = random.uniform(bounds_.y_min, bounds_.y_max);
    if (checker_.isFree({x, y})) return Point2{x, y};
  }
  return std::nullopt;
}

}  // namespace roomba_rrt::planning
