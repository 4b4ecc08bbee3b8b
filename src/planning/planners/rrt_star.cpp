#include "roomba_rrt/planning/planners/rrt_star.h"

#include <cmath>
#include <limits>
#include <vector>

namespace roomba_rrt::planning {
namespace {

// The cost (path length from the root) of every node, kept right under rewiring. Children are
// linked lists in flat arrays (first child, next sibling), so re-parenting a node updates its
// whole subtree without a heap object per node.
class CostsFromRoot {
 public:
  void addRoot() { push(0.0); }
  void add(int parent, double cost) {
    const int node = push(cost);
    link(node, parent);
  }
  double operator()(int node) const { return cost_[node]; }

  // Moves `node` (with its subtree) under `new_parent`, where it costs `new_cost`.
  void reparent(Tree& tree, int node, int new_parent, double new_cost) {
    unlink(node, tree.parent[node]);
    link(node, new_parent);
    tree.parent[node] = new_parent;
    const double delta = new_cost - cost_[node];
    stack_.assign(1, node);
    while (!stack_.empty()) {
      const int v = stack_.back();
      stack_.pop_back();
      cost_[v] += delta;
      for (int c = first_child_[v]; c >= 0; c = next_sibling_[c]) stack_.push_back(c);
    }
  }

 private:
  int push(double cost) {
    cost_.push_back(cost);
    first_child_.push_back(-1);
    next_sibling_.push_back(-1);
    return static_cast<int>(cost_.size()) - 1;
  }
  void link(int node, int parent) {
    next_sibling_[node] = first_child_[parent];
    first_child_[parent] = node;
  }
  void unlink(int node, int parent) {
    int* slot = &first_child_[parent];
    while (*slot != node) slot = &next_sibling_[*slot];
    *slot = next_sibling_[node];
  }

  std::vector<double> cost_;
  std::vector<int> first_child_, next_sibling_;
  std::vector<int> stack_;
};

// The shrinking neighbourhood radius of RRT* in the plane, never below one step.
double rewireRadius(const Bounds& bounds, double step, int n) {
  const double area = (bounds.x_max - bounds.x_min) * (bounds.y_max - bounds.y_min);
  const double gamma = 2.0 * std::sqrt(1.5) * std::sqrt(area / M_PI);
  return std::max(step, n > 1 ? gamma * std::sqrt(std::log(n) / n) : 0.0);
}

}  // namespace

PlanResult solveRrtStar(const Problem& problem, const PlannerOptions& options, PlannerParts parts,
                        const ProgressCallback& progress) {
  constexpr double kImprovement = 1e-12;  // rewire only for a real gain (no float ping-pong)
  PlanResult result;
  Tree& tree = result.tree;
  plantTree(tree, parts.nearest, problem.start, problem.bounds);
  tree.reserve(nodeCapacity(options.max_iterations));
  CostsFromRoot cost;
  cost.addRoot();
  std::vector<int> near;
  std::vector<int> at_goal;
  StopCondition never;
  StopCondition& stop = parts.stop != nullptr ? *parts.stop : never;

  bool stopped = false;  // by the time budget or a stop request: keep the best path so far
  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    if (stop()) {
      stopped = true;
      break;
    }
    result.iterations = iteration;
    // 1. Sample exactly as RRT does (goal bias, then rejection sampling).
    const std::optional<Point2> sample = sampleTarget(problem, options, parts);
    if (!sample) {
      setNoPath(result, noFreeSpaceMessage(parts.sampler));
      return result;
    }
    // 2.-4. Nearest node, one step towards the sample, collision check, exactly as RRT does
    //       (skip the iteration if blocked or no step at all); RRT* differs in the insertion.
    const std::optional<Extension> motion =
        steerFromNearest(parts.nearest, parts.checker, *sample, options.step);
    if (!motion) {
      progress(tree, iteration);
      continue;
    }
    const Point2 q_new = motion->q_new;
    // 5. Choose the parent: the neighbour through which q_new is reached shortest. Its edge can
    //    be far longer than one step, so it is checked whole in both modes (points mode checks
    //    only the single step from the nearest node by its end).
    parts.nearest.withinRadius(q_new, rewireRadius(problem.bounds, options.step, tree.size()),
                               near);
    int parent = motion->from;
    double new_cost = cost(motion->from) + distance(motion->q_from, q_new);
    for (int n : near) {
      const double c = cost(n) + distance(tree.nodes[n], q_new);
      if (c < new_cost && parts.checker.isSegmentFree(tree.nodes[n], q_new)) {
        parent = n;
        new_cost = c;
      }
    }
    const int added = tree.add(q_new, parent);
    parts.nearest.add(q_new, added);
    cost.add(parent, new_cost);
    // 6. Rewire: neighbours that get shorter through q_new take it as parent (edge checked whole).
    for (int n : near) {
      const double via_new = new_cost + distance(q_new, tree.nodes[n]);
      if (n != parent && via_new + kImprovement < cost(n) &&
          parts.checker.isSegmentFree(q_new, tree.nodes[n])) {
        cost.reparent(tree, n, added, via_new);
      }
    }
    // 7. Remember nodes at the goal; keep improving until the iterations are used.
    if (distance(q_new, problem.goal) < options.goal_tolerance) at_goal.push_back(added);
    progress(tree, iteration);
  }
  // The cheapest node at the goal gives the path.
  int best = -1;
  double best_cost = std::numeric_limits<double>::infinity();
  for (int g : at_goal) {
    if (cost(g) < best_cost) {
      best = g;
      best_cost = cost(g);
    }
  }
  if (best >= 0) {
    setPathToNode(result, best,
                  "best of " + std::to_string(result.iterations) + " iterations" +
                      (stopped ? "; " + stop.reason() : ""));
  } else {
    setNoPath(result, stopped ? stop.reason() : noPathWithin(options.max_iterations));
  }
  return result;
}

}  // namespace roomba_rrt::planning
