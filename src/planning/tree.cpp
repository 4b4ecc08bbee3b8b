#include "roomba_rrt/planning/tree.h"

#include <algorithm>

namespace roomba_rrt::planning {

std::vector<Point2> pathFromRoot(const Tree& tree, int node) {
  std::vector<Point2> path;
  for (int i = node; i >= 0; i = tree.parent[i]) path.push_back(tree.nodes[i]);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace roomba_rrt::planning
