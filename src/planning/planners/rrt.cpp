#include "roomba_rrt/planning/planners/rrt.h"

#include <algorithm>
#include <cmath>

#include "roomba_rrt/planning/nearest_neighbors/grid_nearest_neighbors.h"

namespace roomba_rrt::planning {

void plantTree(Tree& tree, NearestNeighbors& nearest, const Point2& root, const Bounds& bounds) {
  tree.clear();
  nearest.clear(bounds, tree.nodes);
  nearest.add(root, tree.add(root, -1));
}

Point2 steerFar(const Point2& q_near, const Point2& q_rand, double step) {
  // The fraction t = step / d of the way, d from halved differences (they cannot overflow), and
  // the point as the convex combination (1 - t) q_near + t q_rand (it cannot either).
  const double half_d =
      std::hypot(0.5 * q_rand.x - 0.5 * q_near.x, 0.5 * q_rand.y - 0.5 * q_near.y);
  const double t = std::min(1.0, 0.5 * step / half_d);  // 0 when even half_d overflows
  return {(1 - t) * q_near.x + t * q_rand.x, (1 - t) * q_near.y + t * q_rand.y};
}

std::size_t nodeCapacity(int max_iterations) {
  // A run adds at most one node per iteration. Reserving more than a few million is pointless:
  // a run allowed that many iterations usually stops long before, and the arrays can still grow.
  constexpr std::size_t kCap = std::size_t{1} << 22;
  return std::min(static_cast<std::size_t>(std::max(max_iterations, 0)) + 1, kCap);
}

std::string noFreeSpaceMessage(const FreeSpaceSampler& sampler) {
  return "sampling: no free point in " + std::to_string(sampler.maxTries()) +
         " draws; the obstacles leave no room in the bounds";
}

namespace {

/// A tree's index that also keeps the node nearest to the goal up to date as nodes are added:
/// with goal bias p, a fraction p of the targets is the goal, and those need no search. Its
/// answers are the index's (the smallest squared distance, the lowest index among equals).
template <typename Index>
class GoalAwareIndex {
 public:
  GoalAwareIndex(Index& index, const Point2& goal, const Point2& root)
      : index_(index), goal_(goal), best_{0, root}, best_d2_(squaredDistance(root, goal)) {}

  Neighbor nearestNeighbor(const Point2& q) const {
    return q.x == goal_.x && q.y == goal_.y ? best_ : index_.nearestNeighbor(q);
  }
  void add(const Point2& p, int index) {
    index_.add(p, index);
    const double d2 = squaredDistance(p, goal_);
    if (d2 < best_d2_) {  // strict: an equally near node added earlier has the lower index
      best_d2_ = d2;
      best_ = {index, p};
    }
  }

 private:
  Index& index_;
  Point2 goal_;
  Neighbor best_;
  double best_d2_;
};

/// solveRrt() with `index` (which is parts.nearest) called through its type `Index`.
template <typename Index>
PlanResult growRrt(const Problem& problem, const PlannerOptions& options, PlannerParts parts,
                   Index& index, const ProgressCallback& progress) {
  PlanResult result;
  Tree& tree = result.tree;
  plantTree(tree, index, problem.start, problem.bounds);
  tree.reserve(nodeCapacity(options.max_iterations));  // the arrays never move while it grows
  GoalAwareIndex<Index> nearest(index, problem.goal, problem.start);
  StopCondition never;
  StopCondition& stop = parts.stop != nullptr ? *parts.stop : never;

  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    // Asked every 16th iteration: an RRT iteration is short, and a counter the loop keeps in a
    // register is cheaper than the condition's own countdown in memory.
    if (iteration % 16 == 0 && stop()) {
      setNoPath(result, stop.reason());
      return result;
    }
    result.iterations = iteration;
    // 1. Sample: the goal with probability p, otherwise a free point (bounded rejection).
    const std::optional<Point2> q_rand = sampleTarget(problem, options, parts);
    if (!q_rand) {
      setNoPath(result, noFreeSpaceMessage(parts.sampler));
      return result;
    }
    // 2.-5. Nearest node, one step towards q_rand, collision check, insert.
    const int added = extendTree(tree, nearest, parts.checker, *q_rand, options.step);
    // 6. Stop when the new node is within epsilon of the goal.
    if (added >= 0 && distance(tree.nodes[added], problem.goal) < options.goal_tolerance) {
      setPathToNode(result, added);
      return result;
    }
    progress(tree, iteration);
  }
  setNoPath(result, noPathWithin(options.max_iterations));
  return result;
}

}  // namespace

PlanResult solveRrt(const Problem& problem, const PlannerOptions& options, PlannerParts parts,
                    const ProgressCallback& progress) {
  // The default index, the grid, is called by its own type: its small-tree paths (the lab's
  // trees) are then inlined into the loop instead of being two virtual calls per iteration.
  if (auto* grid = dynamic_cast<GridNearestNeighbors*>(&parts.nearest)) {
    return growRrt(problem, options, parts, *grid, progress);
  }
  return growRrt(problem, options, parts, parts.nearest, progress);
}

}  // namespace roomba_rrt::planning
