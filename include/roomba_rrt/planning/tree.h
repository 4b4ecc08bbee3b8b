// The search tree in the lab's flat layout: one array of positions, one of parent indices.
#pragma once

#include <vector>

#include "roomba_rrt/planning/geometry.h"

namespace roomba_rrt::planning {

/// nodes[i] has parent parent[i]; a root has parent -1. Node 0 is the start.
/// RRT-Connect stores both of its trees here: the goal tree follows the start tree and its root
/// (the goal) also has parent -1, so it has size() - 2 edges instead of size() - 1.
struct Tree {
  std::vector<Point2> nodes;
  std::vector<int> parent;

  int size() const { return static_cast<int>(nodes.size()); }
  /// Appends a node and returns its index.
  int add(const Point2& p, int parent_index) {
    nodes.push_back(p);
    parent.push_back(parent_index);
    return size() - 1;
  }
  void clear() {
    nodes.clear();
    parent.clear();
  }
  void reserve(std::size_t n) {
    nodes.reserve(n);
    parent.reserve(n);
  }
};

/// The positions from the root of `node`'s tree down to `node` (root first).
std::vector<Point2> pathFromRoot(const Tree& tree, int node);

}  // namespace roomba_rrt::planning
