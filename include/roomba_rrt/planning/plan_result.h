// What a planner returns.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "roomba_rrt/planning/geometry.h"
#include "roomba_rrt/planning/tree.h"

namespace roomba_rrt::planning {

struct PlanResult {
  bool success = false;
  std::string message;       ///< what happened; names the field on invalid input
  std::vector<Point2> path;  ///< start ... (within epsilon of) goal; empty on failure
  double length = std::numeric_limits<double>::infinity();  ///< +inf on failure
  int iterations = 0;        ///< iterations used (max_iterations on failure)
  Tree tree;                 ///< the tree(s) grown (see Tree for RRT-Connect)
  double planning_time = 0;  ///< wall-clock seconds
};

}  // namespace roomba_rrt::planning
