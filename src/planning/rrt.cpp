#include "roomba_rrt/planning/rrt.h"

namespace roomba_rrt::planning {

Point2 steer(const Point2& q_near, const Point2& q_rand, double step) {
  const double d = distance(q_near, q_rand);
  if (d <= step) return q_rand;
  // q_near + step * (q_rand - q_near) / d, evaluated in the lab's order.
  return {q_near.x + step * (q_rand.x - q_near.x) / d, q_near.y + step * (q_rand.y - q_near.y) / d};
}

void plantTree(Tree& tree, NearestNeighbors& nearest, const Point2& root, const Bounds& bounds) {
  tree.clear();
  nearest.clear(bounds);
  nearest.add(root, tree.add(root, -1));
}

std::optional<Point2> sampleTarget(const Problem& problem, const PlannerOptions& options,
                                   const PlannerParts& parts) {
  if (parts.random.uniform() < options.goal_bias) return problem.goal;
  return parts.sampler.sample(parts.random);
}

int extendTree(Tree& tree, NearestNeighbors& nearest, const CollisionChecker& checker,
               const Point2& target, double step) {
  // Nearest tree node.
  const auto [near, q_near] = nearest.nearestNeighbor(target);
  // Extend from it by at most one step.
  const Point2 q_new = steer(q_near, target, step);
  // Check the new node (points) or the new edge (segments); a collision wastes the iteration.
  // A step of length zero (the target is already a node, e.g. the goal with epsilon = 0) adds
  // nothing either; it never happens in the lab's runs, which stop at the goal.
  if (!checker.isMotionFree(q_near, q_new)) return -1;
  if (q_new.x == q_near.x && q_new.y == q_near.y) return -1;
  // Insert it with q_near as parent.
  const int added = tree.add(q_new, near);
  nearest.add(q_new, added);
  return added;
}

std::string noFreeSpaceMessage(const FreeSpaceSampler& sampler) {
  return "sampling: no free point in " + std::to_string(sampler.maxTries()) +
         " draws; the obstacles leave no room in the bounds";
}

PlanResult solveRrt(const Problem& problem, const PlannerOptions& options, PlannerParts parts,
                    const ProgressCallback& progress) {
  PlanResult result;
  Tree& tree = result.tree;
  plantTree(tree, parts.nearest, problem.start, problem.bounds);

  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    result.iterations = iteration;
    // 1. Sample: the goal with probability p, otherwise a free point (bounded rejection).
    const std::optional<Point2> q_rand = sampleTarget(problem, options, parts);
    if (!q_rand) {
      result.message = noFreeSpaceMessage(parts.sampler);
      return result;
    }
    // 2.-5. Nearest node, one step towards q_rand, collision check, insert.
    const int added = extendTree(tree, parts.nearest, parts.checker, *q_rand, options.step);
    // 6. Stop when the new node is within epsilon of the goal.
    if (added >= 0 && distance(tree.nodes[added], problem.goal) < options.goal_tolerance) {
      result.success = true;
      result.path = pathFromRoot(tree, added);
      result.length = pathLength(result.path);
      result.message = "path found";
      return result;
    }
    progress(tree, iteration);
  }
  result.message = "no path within " + std::to_string(options.max_iterations) + " iterations";
  return result;
}

}  // namespace roomba_rrt::planning
