#include "roomba_rrt/planning/geometry.h"

namespace roomba_rrt::planning {

double pathLength(const std::vector<Point2>& path) {
  double length = 0;
  for (std::size_t i = 1; i < path.size(); ++i) length += distance(path[i - 1], path[i]);
  return length;
}

}  // namespace roomba_rrt::planning
