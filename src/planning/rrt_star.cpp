#include "roomba_rrt/planning/rrt_star.h"

#include <cmath>
#include <limits>

namespace roomba_rrt::planning {
namespace {

// Length of the tree path from the root to `node`. Walking the parents (rather than caching a
// cost per node) keeps the costs right after every rewiring without child lists; on the lab's
// trees (a few thousand nodes, depth ~50) it is cheap.
double costToCome(const Tree& tree, int node) {
  double cost = 0;
  for (int i = node; tree.parent[i] >= 0; i = tree.parent[i]) {
    cost += distance(tree.nodes[i], tree.nodes[tree.parent[i]]);
  }
  return cost;
}

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
  std::vector<int> near;
  std::vector<int> at_goal;

  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    result.iterations = iteration;
    // 1. Sample exactly as RRT does (goal bias, then rejection sampling).
    const std::optional<Point2> sample = sampleTarget(problem, options, parts);
    if (!sample) {
      result.message = noFreeSpaceMessage(parts.sampler);
      return result;
    }
    const Point2 q_rand = *sample;
    // 2. Nearest node and 3. one step towards the sample; 4. skip if blocked.
    const int nearest = parts.nearest.nearest(q_rand);
    const Point2 q_new = steer(tree.nodes[nearest], q_rand, options.step);
    if (!parts.checker.isMotionFree(tree.nodes[nearest], q_new)) {
      progress(tree, iteration);
      continue;
    }
    // 5. Choose the parent: the neighbour through which q_new is reached shortest.
    parts.nearest.withinRadius(q_new, rewireRadius(problem.bounds, options.step, tree.size()),
                               near);
    int parent = nearest;
    double new_cost = costToCome(tree, nearest) + distance(tree.nodes[nearest], q_new);
    for (int n : near) {
      const double c = costToCome(tree, n) + distance(tree.nodes[n], q_new);
      if (c < new_cost && parts.checker.isMotionFree(tree.nodes[n], q_new)) {
        parent = n;
        new_cost = c;
      }
    }
    const int added = tree.add(q_new, parent);
    parts.nearest.add(q_new, added);
    // 6. Rewire: neighbours that get shorter through q_new take it as parent.
    for (int n : near) {
      const double via_new = new_cost + distance(q_new, tree.nodes[n]);
      if (n != parent && via_new + kImprovement < costToCome(tree, n) &&
          parts.checker.isMotionFree(q_new, tree.nodes[n])) {
        tree.parent[n] = added;
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
    const double c = costToCome(tree, g);
    if (c < best_cost) {
      best = g;
      best_cost = c;
    }
  }
  if (best >= 0) {
    result.success = true;
    result.path = pathFromRoot(tree, best);
    result.length = pathLength(result.path);
    result.message =
        "path found (best of " + std::to_string(options.max_iterations) + " iterations)";
  } else if (result.message.empty()) {
    result.message = "no path within " + std::to_string(options.max_iterations) + " iterations";
  }
  return result;
}

}  // namespace roomba_rrt::planning
