#include "roomba_rrt/planning/tree.h"

namespace roomba_rrt::planning {

std::vector<Point2> pathFromRoot(const Tree& tree, int node) {
  // Counted first, then filled from the end: one allocation, no reversal.
  std::size_t length = 0;
  for (int i = node; i >= 0; i = tree.parent[i]) ++length;
  std::vector<Point2> path(length);
  for (int i = node; i >= 0; i = tree.parent[i]) path[--length] = tree.nodes[i];
  return path;
}

}  // namespace roomba_rrt::planning
