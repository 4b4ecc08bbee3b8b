// A planning query: where from, where to, what is in the way, where to sample.
#pragma once

#include <vector>

#include "roomba_rrt/planning/geometry.h"

namespace roomba_rrt::planning {

struct Problem {
  Point2 start;
  Point2 goal;
  std::vector<Circle> obstacles;
  Bounds bounds;
};

}  // namespace roomba_rrt::planning
