#include "roomba_rrt/planning/planners/rrt_connect.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace roomba_rrt::planning {
namespace {

// One of the two trees with its nearest-neighbour structure.
struct GrowingTree {
  Tree tree;
  NearestNeighbors& nearest;

  void plant(const Point2& root, const Bounds& bounds) { plantTree(tree, nearest, root, bounds); }
};

// The extension steps of a run, connect steps included: each one counts against
// max_iterations and asks the stop condition.
class StepBudget {
 public:
  StepBudget(int max_steps, StopCondition& stop) : max_steps_(max_steps), stop_(stop) {}
  /// Takes one step; false when none is left (iterations used up, or told to stop).
  bool take() {
    if (used_ >= max_steps_ || stop_()) return false;
    ++used_;
    return true;
  }
  int used() const { return used_; }

 private:
  int used_ = 0;
  int max_steps_;
  StopCondition& stop_;
};

// One step of tree `t` towards `target` (extendTree()); the new node's index, or -1 if blocked.
int extend(GrowingTree& t, const Point2& target, const PlannerOptions& options,
           const CollisionChecker& checker) {
  return extendTree(t.tree, t.nearest, checker, target, options.step);
}

// Steps towards `target` until it is reached (returns that node), blocked or out of steps
// (returns -1). The last step lands exactly on the target (steer returns it when within one step).
int connect(GrowingTree& t, const Point2& target, const PlannerOptions& options,
            const CollisionChecker& checker, StepBudget& budget) {
  while (budget.take()) {
    const int added = extend(t, target, options, checker);
    if (added < 0) return -1;
    const Point2& reached = t.tree.nodes[added];
    if (reached.x == target.x && reached.y == target.y) return added;
  }
  return -1;
}

// The path through the junction where the trees met: start tree root ... `in_start` (a node
// of the start tree) = `in_goal` (a node of the goal tree) ... goal tree root.
std::vector<Point2> joinedPath(const Tree& start_tree, int in_start, const Tree& goal_tree,
                               int in_goal) {
  std::vector<Point2> path = pathFromRoot(start_tree, in_start);
  std::vector<Point2> tail = pathFromRoot(goal_tree, in_goal);
  path.insert(path.end(), tail.rbegin() + 1, tail.rend());  // the junction once
  return path;
}

// Both trees in one: the goal tree's nodes follow the start tree's, parents shifted.
Tree merge(const Tree& start_tree, const Tree& goal_tree) {
  Tree merged;
  merged.reserve(start_tree.nodes.size() + goal_tree.nodes.size());
  merged.nodes = start_tree.nodes;  // into the reserved arrays: one allocation each
  merged.parent = start_tree.parent;
  const int offset = start_tree.size();
  for (int i = 0; i < goal_tree.size(); ++i) {
    const int p = goal_tree.parent[i];
    merged.add(goal_tree.nodes[i], p < 0 ? -1 : p + offset);
  }
  return merged;
}

}  // namespace

PlanResult solveRrtConnect(const Problem& problem, const PlannerOptions& options,
                           PlannerParts parts, const ProgressCallback& progress) {
  auto goal_index = makeNearestNeighbors(options.nearest);
  GrowingTree start_tree{{}, parts.nearest};
  GrowingTree goal_tree{{}, *goal_index};
  start_tree.plant(problem.start, problem.bounds);
  goal_tree.plant(problem.goal, problem.bounds);
  // Room for the trees of a short plan, so they are not copied as they start to grow (a room's
  // plan adds about 30 nodes); larger trees double as vectors do.
  constexpr std::size_t kFirstCapacity = 256;
  for (GrowingTree* t : {&start_tree, &goal_tree}) {
    t->tree.reserve(std::min(nodeCapacity(options.max_iterations), kFirstCapacity));
  }
  GrowingTree* active = &start_tree;
  GrowingTree* other = &goal_tree;

  PlanResult result;
  StopCondition never;
  StopCondition& stop = parts.stop != nullptr ? *parts.stop : never;
  StepBudget budget(options.max_iterations, stop);
  for (int round = 1; budget.take(); ++round) {
    // 1. Sample a free point (no goal bias: the goal tree pulls instead).
    const auto q_rand = parts.sampler.sample(parts.random);
    if (!q_rand) {
      setNoPath(result, noFreeSpaceMessage(parts.sampler));
      break;
    }
    // 2. Extend the active tree one step towards it.
    const int added = extend(*active, *q_rand, options, parts.checker);
    if (added >= 0) {
      // 3. Connect the other tree to the new node, step by step.
      const Point2 q_new = active->tree.nodes[added];
      const int reached = connect(*other, q_new, options, parts.checker, budget);
      if (reached >= 0) {
        // 4. A path: start tree root ... junction ... goal tree root.
        const bool start_active = active == &start_tree;
        setPathFound(result, joinedPath(start_tree.tree, start_active ? added : reached,
                                        goal_tree.tree, start_active ? reached : added));
        break;
      }
    }
    // 5. Swap the roles of the trees.
    std::swap(active, other);
    if (progress.call && progress.every > 0 && round % progress.every == 0) {
      progress(merge(start_tree.tree, goal_tree.tree), round);
    }
  }
  result.iterations = budget.used();
  if (!result.success && result.message.empty()) {
    setNoPath(result, !stop.reason().empty()
                          ? stop.reason()
                          : noPathWithin(options.max_iterations) + " (connect steps included)");
  }
  result.tree = merge(start_tree.tree, goal_tree.tree);
  return result;
}

}  // namespace roomba_rrt::planning
