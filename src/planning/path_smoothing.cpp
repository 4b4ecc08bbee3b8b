#include "roomba_rrt/planning/path_smoothing.h"

#include <utility>

#include "roomba_rrt/planning/lab/matlab_random.h"

namespace roomba_rrt::planning {

std::vector<Point2> shortcutPath(std::vector<Point2> path, const CollisionChecker& checker,
                                 int tries, std::uint32_t seed) {
  MatlabRandom random(seed);
  for (int t = 0; t < tries && path.size() > 2; ++t) {
    const double n = static_cast<double>(path.size());
    auto i = static_cast<std::size_t>(random.uniform() * n);
    auto j = static_cast<std::size_t>(random.uniform() * n);
    if (i > j) std::swap(i, j);
    if (j - i < 2) continue;  // neighbours: nothing to cut
    if (checker.isSegmentFree(path[i], path[j])) {
      path.erase(path.begin() + static_cast<std::ptrdiff_t>(i + 1),
                 path.begin() + static_cast<std::ptrdiff_t>(j));
    }
  }
  return path;
}

}  // namespace roomba_rrt::planning
