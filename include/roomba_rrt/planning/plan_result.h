// What a planner returns, and the two ways every planner ends a run (with a path, or without one
// and a message saying why), so that the three planners' results read the same.
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

/// Ends a run with `path` (start first): success, the path, its length, and the message
/// "path found", or "path found (<note>)" when a note is given.
void setPathFound(PlanResult& result, std::vector<Point2> path, const std::string& note = "");

/// setPathFound() with the path from the root of result.tree down to `node`.
void setPathToNode(PlanResult& result, int node, const std::string& note = "");

/// Ends a run without a path: success false, no path, and `why` as the message (the stop
/// condition's reason, noFreeSpaceMessage(), noPathWithin(), or validate()'s message).
void setNoPath(PlanResult& result, std::string why);

/// "no path within N iterations": the iterations ran out before a path was found.
std::string noPathWithin(int max_iterations);

}  // namespace roomba_rrt::planning
