#include "roomba_rrt/planning/plan_result.h"

#include <utility>

namespace roomba_rrt::planning {

void setPathFound(PlanResult& result, std::vector<Point2> path, const std::string& note) {
  result.success = true;
  result.path = std::move(path);
  result.length = pathLength(result.path);
  result.message = note.empty() ? "path found" : "path found (" + note + ")";
}

void setPathToNode(PlanResult& result, int node, const std::string& note) {
  setPathFound(result, pathFromRoot(result.tree, node), note);
}

void setNoPath(PlanResult& result, std::string why) {
  result.success = false;
  result.path.clear();
  result.length = std::numeric_limits<double>::infinity();
  result.message = std::move(why);
}

std::string noPathWithin(int max_iterations) {
  return "no path within " + std::to_string(max_iterations) + " iterations";
}

}  // namespace roomba_rrt::planning
